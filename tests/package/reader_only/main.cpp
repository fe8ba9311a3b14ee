/* Reads every object of a rawlog with MRPT's archive API only and prints
 * "<n> objects, <k> of class mrpt_fog::CObservationFOG". Exit 1 if reading stopped early. */
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
	if (argc != 2) return 2;
	mrpt::io::CFileGZInputStream f(argv[1]);
	auto ar = mrpt::serialization::archiveFrom(f);
	std::size_t n = 0, fog = 0;
	while (f.getPosition() < f.getTotalBytesCount() || !f.checkEOF())
	{
		try
		{
			const auto obj = ar.ReadObject();
			++n;
			if (std::string(obj->GetRuntimeClass()->className) == "mrpt_fog::CObservationFOG") ++fog;
		}
		catch (const std::exception& e)
		{
			if (f.checkEOF()) break;
			std::printf("%zu objects, %zu of class mrpt_fog::CObservationFOG; stopped: %.160s\n", n, fog, e.what());
			return 1;
		}
	}
	std::printf("%zu objects, %zu of class mrpt_fog::CObservationFOG\n", n, fog);
	return 0;
}
