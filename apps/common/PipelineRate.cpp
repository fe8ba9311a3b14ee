/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "PipelineRate.h"

#include "FieldWarning.h"
#include "RangeWarning.h"
#include "ThermistorScreeningReport.h"

#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::app
{
const heading::RateStep& addFogSample(heading::HeadingPipeline& pipe, const FogSample& x, const std::string& cal_path)
{
	if (cal_path.empty()) return pipe.addFog(x);
	try
	{
		return pipe.addFog(x);
	}
	catch (const std::exception& ex)
	{
		throw std::runtime_error(cal_path + ": cannot compensate the drive's FOG: " + ex.what());
	}
}

std::vector<double> pipelineRate_dph(heading::HeadingPipeline& pipe, const FogSeries& fog,
									 const heading::OdometryPoses& odo, const std::string& cal_path)
{
	constexpr double nan = std::numeric_limits<double>::quiet_NaN();
	std::vector<double> rate(fog.size());
	FogSample x;
	x.temp_C.resize(fog.thermistors.size());
	std::size_t j = 0;
	const auto odometryUpTo = [&](double t) {
		for (; j < odo.t_s.size() && odo.t_s[j] <= t; j++) pipe.addOdometry(odo.t_s[j], odo.x_m[j], odo.y_m[j], odo.phi_rad[j]);
	};
	for (std::size_t k = 0; k < fog.size(); k++)
	{
		odometryUpTo(fog.epoch_s + fog.time_s[k]);
		x.time_s = fog.time_s[k];
		for (std::size_t a = 0; a < 3; a++) x.rate_dph[a] = fog.has_axis[a] ? fog.rate_dph[a][k] : nan;
		for (std::size_t i = 0; i < x.temp_C.size(); i++) x.temp_C[i] = fog.temp_C[i][k];
		x.field_uT = fog.field_uT.empty() ? nan : fog.field_uT[k];
		x.power = fog.power.empty() ? nan : fog.power[k];
		rate[k] = addFogSample(pipe, x, cal_path).integrated_dph;
	}
	odometryUpTo(std::numeric_limits<double>::infinity());  // the rest: the last standstill's updates
	return rate;
}

std::string reportPipelineCompensation(const heading::HeadingPipeline& pipe, const Calibration& zcal,
									   bool screen_thermistors, bool log_has_field)
{
	ThermistorScreening screening;
	const std::vector<ThermistorHealthCounters> health = pipe.screeningCounters();
	for (std::size_t i = 0; i < health.size(); i++)
	{
		screening.names.push_back(pipe.header().thermistors[i].name);
		screening.counters.push_back(health[i]);
		screening.rejected_readings += health[i].out_of_range + health[i].spike + health[i].stuck;
	}
	if (!screen_thermistors || screening.rejected_readings)
		std::fputs(screeningText(screening, screen_thermistors).c_str(), stdout);
	const CompensationCounters& c = *pipe.compensationCounters();
	if (c.fallback_samples || c.no_model_samples || c.clamped_samples)
		std::printf("  compensation: %zu samples, %zu on a fallback model, %zu without model, %zu clamped to the "
					"calibrated range\n",
					c.samples, c.fallback_samples, c.no_model_samples, c.clamped_samples);
	std::fputs(outOfRangeWarning(c, zcal.extrapolation).c_str(), stdout);
	const std::string w = fieldWarning(zcal, c, log_has_field);
	std::fputs(w.c_str(), stderr);
	return w;
}

}  // namespace mrpt_fog::app
