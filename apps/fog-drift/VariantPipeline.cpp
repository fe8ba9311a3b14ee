/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "VariantPipeline.h"


#include <mrpt/core/Clock.h>
#include <mrpt_fog_heading/StandstillCorrection.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::drift
{
heading::PipelineOptions pipelineOptionsFor(const HeadingOptions& hopt)
{
	heading::PipelineOptions o;
	o.latitude_deg = hopt.latitude_deg;
	o.sampling = hopt.sampling;
	o.alignment = heading::Alignment::ByCaller;
	o.field_refinement = false;
	return o;
}

heading::PipelineOptions compensatedOptionsFor(const DriveSettings& st, const HeadingOptions& hopt, bool refine,
											   const std::optional<FieldOffset>& field_offset)
{
	heading::PipelineOptions o = pipelineOptionsFor(hopt);
	o.screen_thermistors = st.screen_thermistors;
	o.earth.calibration_latitude_deg = st.cal_latitude_deg;
	o.earth.bias_without_earth_rate = st.cal_no_earth_rate;
	o.field_offset = field_offset;
	o.field_refinement = refine;
	o.field.turn_on_repeatability_dph = st.refinement.turn_on_repeatability_dph;
	o.field.noise = st.refinement.noise;
	o.field.standstill = st.refinement.standstill;
	o.field.min_still_s = st.refinement.min_still_s;
	o.field.guard_s = st.refinement.guard_s;
	o.field.significance_sigma = st.refinement.significance_sigma;
	return o;
}

std::unique_ptr<heading::HeadingPipeline> compensatedPipeline(const FogSeries& header, const Calibration& zcal,
															  const DriveSettings& st, const HeadingOptions& hopt,
															  double t0_unix_s, bool refine, DriveEvaluation& e)
{
	// What the calibration learned in the field (fog-refine), at the drive's date
	e.refinement.calibration_offset = loadFieldOffset(st.cal_path);
	if (e.refinement.calibration_offset)
		e.refinement.calibration_offset_at_drive_dph = e.refinement.calibration_offset->offsetAt_dph(t0_unix_s);
	const heading::PipelineOptions o = compensatedOptionsFor(st, hopt, refine, e.refinement.calibration_offset);
	try
	{
		return std::make_unique<heading::HeadingPipeline>(header, o, &zcal);
	}
	catch (const std::exception& ex)
	{
		throw std::runtime_error(st.cal_path + ": cannot compensate the drive's FOG: " + ex.what());
	}
}

FogSample fogSampleOf(const CObservationFOG& o, double epoch_s)
{
	constexpr double nan = std::numeric_limits<double>::quiet_NaN();
	FogSample x;
	x.time_s = mrpt::Clock::toDouble(o.timestamp) - epoch_s;
	for (std::size_t a = 0; a < 3; a++) x.rate_dph[a] = o.hasAxis[a] ? o.rate_dph[a] : nan;
	x.temp_C.resize(o.thermistors.size());
	for (std::size_t i = 0; i < x.temp_C.size(); i++) x.temp_C[i] = o.temperature_C(i);
	x.table_rate_dph = o.hasTableRate ? o.tableRate_dph : nan;
	x.field_uT = o.hasField ? o.field_uT : nan;
	x.power = o.hasPower ? (o.powerOn ? 1.0 : 0.0) : nan;
	return x;
}

void reportCompensation(heading::HeadingPipeline& pipe, const Calibration& zcal, bool log_has_field,
						const DriveSettings& st, DriveEvaluation& e)
{
	e.magnetic_term |= zcal.magnetic.has_value();
	e.field_warning += app::reportPipelineCompensation(pipe, zcal, st.screen_thermistors, log_has_field);

	auto* standstill = dynamic_cast<heading::StandstillCorrection*>(pipe.rateCorrection());
	if (!standstill) return;
	standstill->finish();
	const nav::FieldBiasRefiner* f = standstill->refiner();
	if (!f) return;
	FieldRefinementResult& r = e.refinement;
	noteRefinement(*f, r);
	r.prior_offset_dph = f->options().prior_offset_dph;
	r.prior_sigma_dph = f->options().prior_sigma_dph;
	r.thermal_sigma_dph = heading::thermalModelSigma_dph(zcal);
	r.expected_rate_dph = pipe.driveEarthRate_dph();  // what the gyro reads while still
	r.significance_sigma = f->options().significance_sigma;
}

}  // namespace mrpt_fog::drift
