/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RawlogObjectReader.h
 * Any MRPT rawlog, object by object, in either format, with every observation class:
 *  - observations-only: one CObservation per object;
 *  - actions-observations: CActionCollection and CSensoryFrame objects, alternating.
 * next() returns the top-level objects as they stand (a sensory frame with its observations, an
 * action collection with its actions), so that a program can pass every object it does not
 * change on unchanged, in order and in the input's format (RawlogObjectWriter).
 *
 * The hostile-input guarantees of FogLogReader hold (docs/validation/hardening.md): each object's header is
 * checked before MRPT reads it (only an observation, a sensory frame or an action collection at
 * the top level; observations in a frame; actions in a collection), frames and collections are
 * read here with their counts bounded, and everything else is read by MRPT under a bounded-
 * allocation guard (ReadLimits::max_object_allocation_bytes per allocation). A defect throws
 * FogIoError saying how many objects were read, where it stopped and why. Memory: one object. */

#include <mrpt/serialization/CSerializable.h>
#include <mrpt_fog/io/FogLogReader.h>

#include <cstdint>
#include <memory>
#include <string>

namespace mrpt_fog
{
class RawlogObjects;

/** The two rawlog formats MRPT writes. */
enum class RawlogFormat
{
	ObservationsOnly,  //!< a CObservation per object
	ActionsObservations  //!< CActionCollection + CSensoryFrame objects
};
const char* rawlogFormatName(RawlogFormat f);  //!< "observations-only", "actions-observations"

class RawlogObjectReader
{
   public:
	explicit RawlogObjectReader(const std::string& path, const ReadLimits& limits = {});
	~RawlogObjectReader();
	RawlogObjectReader(const RawlogObjectReader&) = delete;
	RawlogObjectReader& operator=(const RawlogObjectReader&) = delete;

	/** The next top-level object (a CObservation, CSensoryFrame or CActionCollection); null at
	 * the (checked) end of the file. Throws FogIoError. */
	mrpt::serialization::CSerializable::Ptr next();
	std::size_t objectsRead() const;
	/** The format of what was read so far: ActionsObservations once a frame or a collection was met. */
	RawlogFormat format() const;
	std::uint64_t fileBytesRead() const;
	std::uint64_t fileBytes() const;  //!< 0 when unknown

   private:
	std::unique_ptr<RawlogObjects> impl_;
};

/** A gz-compressed rawlog written object by object, atomically (common/AtomicFile.h: nothing
 * under the output's name before close(); an exception or destruction without close() leaves a
 * previous file intact). */
class RawlogObjectWriter
{
   public:
	explicit RawlogObjectWriter(const std::string& path);
	~RawlogObjectWriter();
	RawlogObjectWriter(const RawlogObjectWriter&) = delete;
	RawlogObjectWriter& operator=(const RawlogObjectWriter&) = delete;

	void write(const mrpt::serialization::CSerializable& obj);
	void close();
	std::size_t objectsWritten() const { return written_; }

	class Impl;

   private:
	std::unique_ptr<Impl> impl_;
	std::size_t written_ = 0;
};

}  // namespace mrpt_fog
