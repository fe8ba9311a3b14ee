/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/* Internal to the obs room (used by io's rawlog reader): a fast decoder of CObservationFOG,
 * defined in obs/CObservationFOG.cpp beside the serialization it mirrors. */

#include <mrpt/poses/CPose3D.h>
#include <mrpt_fog/obs/CObservationFOG.h>

#include <cstddef>
#include <string>

namespace mrpt_fog::detail
{
/** A sensor pose and its bytes as MRPT's CArchive writes it (object header, data, end flag). */
struct SerializedPose
{
	mrpt::poses::CPose3D pose;
	std::string bytes;
};

/** MRPT's serialization of a pose (what `archive << pose` writes). */
std::string serializedPoseBytes(const mrpt::poses::CPose3D& pose);

/** Decodes one whole CObservationFOG as MRPT's CArchive stores it (class-name header, version 0
 * body, end flag) from the contiguous bytes p[0, n) into `o`, without MRPT's per-object class
 * lookup, allocation and per-field stream calls. Returns the bytes used, or 0 when the bytes are
 * not such an object, are cut short, hold a value CObservationFOG::serializeFrom refuses, or a
 * sensor pose other than `pose` (compared byte for byte): then nothing is decided (o may be
 * half-filled) and the caller reads the object through CArchive, which decodes it or says why
 * not. A decoded object equals what serializeFrom gives (test FogRawlog.FastPathEqualsArchive). */
std::size_t decodeFogObservation(const unsigned char* p, std::size_t n, const SerializedPose& pose, CObservationFOG& o);

}  // namespace mrpt_fog::detail
