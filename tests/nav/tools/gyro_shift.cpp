/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** gyro-shift: a test generator independent of the code under test (the compensator, the
 * standstill refinement): copies a rawlog object by object with MRPT's own archive, adding a
 * constant to one CObservationFOG label's z rate while the gyro is powered; every other object
 * (the ideal FOG, odometry, truth, metadata) is written back unchanged, in order.
 *
 *   gyro-shift IN.rawlog OUT.rawlog SHIFT_DPH [LABEL (default FOG) [FROM_S TO_S]]
 *
 * With FROM_S TO_S, timed observations outside [first FOG time + FROM_S, first FOG time + TO_S]
 * are dropped (objects without a time, such as the metadata comment, are kept): a piece of a
 * drive, e.g. one without a standstill.
 * What the field-refinement figures use to add a turn-on offset to the bundled drive
 * (docs/validation/turn-on-refinement.md). */
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/CSerializable.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv)
{
	if (argc != 4 && argc != 5 && argc != 7)
	{
		std::fprintf(stderr, "usage: gyro-shift IN.rawlog OUT.rawlog SHIFT_DPH [LABEL [FROM_S TO_S]]\n");
		return 2;
	}
	try
	{
		mrpt_fog::registerAllClasses_mrpt_fog();
		const std::string label = argc >= 5 ? argv[4] : "FOG";
		const double shift_dph = std::stod(argv[3]);
		const bool cut = argc == 7;
		const double from_s = cut ? std::stod(argv[5]) : 0, to_s = cut ? std::stod(argv[6]) : 0;
		double t_first = NAN;
		mrpt::io::CFileGZInputStream in;
		if (!in.open(argv[1])) throw std::runtime_error(std::string("cannot open ") + argv[1]);
		mrpt::io::CFileGZOutputStream out;
		if (!out.open(argv[2])) throw std::runtime_error(std::string("cannot write ") + argv[2]);
		auto ia = mrpt::serialization::archiveFrom(in);
		auto oa = mrpt::serialization::archiveFrom(out);
		std::size_t objects = 0, shifted = 0, written = 0;
		for (;;)
		{
			mrpt::serialization::CSerializable::Ptr obj;
			try
			{
				ia >> obj;
			}
			catch (const mrpt::serialization::CExceptionEOF&)
			{
				break;
			}
			objects++;
			if (cut)
				if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
					o && o->timestamp != mrpt::Clock::time_point() && !std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(obj))
				{
					const double t = mrpt::Clock::toDouble(o->timestamp);
					if (std::isnan(t_first) && std::dynamic_pointer_cast<mrpt_fog::CObservationFOG>(obj) && o->sensorLabel == label)
						t_first = t;
					if (std::isnan(t_first) || t < t_first + from_s || t > t_first + to_s) continue;
				}
			if (auto f = std::dynamic_pointer_cast<mrpt_fog::CObservationFOG>(obj);
				f && f->sensorLabel == label && f->hasAxis[2] && (!f->hasPower || f->powerOn) && std::isfinite(f->rate_dph[2]))
			{
				f->rate_dph[2] += shift_dph;
				shifted++;
			}
			oa << *obj;
			written++;
		}
		std::printf("gyro-shift: %zu objects read, %zu written, %zu '%s' samples shifted by %g deg/h\n", objects, written,
					shifted, label.c_str(), shift_dph);
		return shifted ? 0 : 1;
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "gyro-shift: %s\n", e.what());
		return 1;
	}
}
