/* A find_package(mrpt_fog) consumer: creates a CObservationFOG, writes it through the library's
 * rawlog writer, reads it back and prints what it got. Exit status 0 only if the values match. */
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <cstdio>
#include <iostream>

int main(int argc, char** argv)
{
	mrpt_fog::registerAllClasses_mrpt_fog();
	auto obs = mrpt_fog::CObservationFOG::Create();
	obs->sensorLabel = "FOG";
	obs->timestamp = mrpt::Clock::fromDouble(1700000000.0);
	obs->setRate_dph(mrpt_fog::GyroAxis::Z, 0.125);
	obs->addThermistor({"Ti1", mrpt_fog::CoilSide::Inner, 0.0}, 25.5);
	obs->getDescriptionAsText(std::cout);

	const std::string path = argc > 1 ? argv[1] : "consumer.rawlog";
	mrpt_fog::writeFogRawlog(path, mrpt_fog::seriesFromObservations({obs}));
	const auto back = mrpt_fog::readFogRawlog(path);
	const bool ok = back.fog.size() == 1 && back.fog.rate_dph[2][0] == 0.125 && back.fog.temp_C[0][0] == 25.5;
	std::printf("consumer: read back %zu sample(s): %s\n", back.fog.size(), ok ? "OK" : "MISMATCH");
	return ok ? 0 : 1;
}
