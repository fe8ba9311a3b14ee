/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "CalibrationChoice.h"

#include "ThermistorScreeningReport.h"

#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/ScaleFactorFit.h>

#include <cstdio>
#include <stdexcept>

namespace mrpt_fog::localize
{
const char* toString(CalibrationSource s)
{
	switch (s)
	{
		case CalibrationSource::Given: return "given";
		case CalibrationSource::FittedBiasAndScaleFactor: return "fitted_bias_and_scale_factor";
		case CalibrationSource::FittedBiasOnly: return "fitted_bias_only";
	}
	return "?";
}

CalibrationChoice chooseCalibration(const CalibrationRequest& request)
{
	CalibrationChoice c;
	if (!request.given_path.empty())
	{
		c.source = CalibrationSource::Given;
		c.path = request.given_path;
		c.cal = loadCalibrationYaml(request.given_path, GyroAxis::Z);
		return c;
	}
	// Thermistor readings screened before the fit, as fog-calibrate and the compensation do.
	const auto screened = [](FogSeries s, const std::string& path) {
		const ThermistorScreening sc = app::screenInPlace(s, true);
		if (sc.rejected_readings > 0)
			std::printf("  %s:\n%s", path.c_str(), app::screeningText(sc, true).c_str());
		return s;
	};
	std::vector<FogSeries> runs{screened(readFogLog(request.chamber_path, "", request.read_options), request.chamber_path)};
	c.fitted_on = {request.chamber_path};
	if (request.ratetable_path)
	{
		runs.push_back(screened(readFogLog(*request.ratetable_path, "", request.read_options), *request.ratetable_path));
		c.fitted_on.push_back(*request.ratetable_path);
		if (!hasTableRates({runs.back()}))
			throw std::runtime_error(*request.ratetable_path +
									 ": no table rates (table_rate_dph) while powered: not a rate-table run");
	}
	FitOptions options;
	// As fog-calibrate --scale-factor auto: the table segments serve the scale factor, not the bias.
	if (request.ratetable_path) options.table_samples = TableSamples::Exclude;
	c.cal = fitCalibration(runs, request.preset, options, c.fitted_on);
	if (request.ratetable_path)
	{
		try
		{
			c.cal.scale_factor = fitScaleFactor(runs, c.cal, {}, nullptr, c.fitted_on);
		}
		catch (const ScaleFactorFitError& e)
		{
			throw std::runtime_error(*request.ratetable_path + ": no scale-factor fit: " + e.what());
		}
		c.source = CalibrationSource::FittedBiasAndScaleFactor;
	}
	else
		c.source = CalibrationSource::FittedBiasOnly;
	c.cal.validation.label = "validation run (none given)";
	c.path = request.write_path;
	saveCalibrationYaml(c.cal, c.path);
	return c;
}

std::string describeCalibration(const CalibrationChoice& choice)
{
	std::string s = choice.path + " (";
	if (choice.source == CalibrationSource::Given)
		s += "given";
	else
	{
		s += "fitted on";
		for (std::size_t i = 0; i < choice.fitted_on.size(); ++i) s += (i ? " + " : " ") + choice.fitted_on[i];
	}
	s += "): bias " + choice.cal.preset;
	char buf[256];
	if (const auto& sf = choice.cal.scale_factor)
	{
		std::snprintf(buf, sizeof(buf), ", scale factor s(T(%s)) order %zu, %.4g ppm/degC over %.1f..%.1f degC",
					  sf->thermistor.c_str(), sf->order(), sf->slope_ppm_per_C, sf->min_C, sf->max_C);
		s += buf;
	}
	else
		s += ", NO scale-factor model (the turn-induced scale-factor error stays in the compensated gyro)";
	return s;
}

}  // namespace mrpt_fog::localize
