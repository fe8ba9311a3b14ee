/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>
#include <stdexcept>

#include "SimulatedSeries.h"

namespace mrpt_fog::sim
{
void SimSettings::validate() const
{
	if (!(rate_hz > 0) || !(rate_hz <= 1000) || !std::isfinite(rate_hz))
		throw std::invalid_argument("rate_hz must be in (0, 1000]");
	for (const auto& id : effects) checkEffectId(id);
}

void recordSimMetadata(FogSeries& series, const std::string& scenario, const ChamberProfile& profile,
					   const FogDevice& device, const SimSettings& settings)
{
	series.setMetadata("sim.generator", "fog-sim (mrpt_fog simulator v1)");
	series.setMetadata("sim.scenario", scenario);
	series.setMetadata("sim.profile", settings.profile_source.empty() ? profile.name() : settings.profile_source);
	series.setMetadata("sim.profile_name", profile.name());
	series.setMetadata("sim.seed", std::to_string(settings.seed));
	series.setMetadata("sim.rng", "mt19937_64 + splitmix64 streams + Box-Muller");
	series.setMetadata("sim.rate_hz", formatValue("%.10g", settings.rate_hz));
	series.setMetadata("sim.effects", effectsToString(settings.effects));
	series.setMetadata("latitude_deg", formatValue("%.10g", device.latitude_deg));
	for (const auto& kv : device.describe()) series.setMetadata("sim." + kv.first, kv.second);
	// A run that starts cold and powered is a turn-on at t = 0 (the simulator's warm-up clock
	// starts there): said for the compensator's and the warm-up fit's turn-on bookkeeping.
	if (profile.initialState() == InitialThermalState::Cold && profile.stateAt(0.0).power_on)
		series.setMetadata("power_on_time_s", "0");
}

namespace
{
struct OptionalColumns
{
	bool table = false, field = false;
};
OptionalColumns optionalColumns(const ChamberProfile& profile)
{
	OptionalColumns c;
	for (const auto& s : profile.segments())
	{
		if (s.kind == ProfileSegment::Kind::Table && s.value != 0) c.table = true;
		if (s.kind == ProfileSegment::Kind::Field && s.value != 0) c.field = true;
	}
	return c;
}

}  // namespace

void simulateChamberSamples(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings,
							double max_time_s, const ChamberSampleSink& f)
{
	settings.validate();
	FogSimulator sim(device, settings.effects, settings.seed);
	const double dt = 1.0 / settings.rate_hz;
	const auto n = static_cast<std::size_t>(std::floor(profile.duration_s() * settings.rate_hz + 1e-9)) + 1;
	for (std::size_t k = 0; k < n; k++)
	{
		const double t = static_cast<double>(k) / settings.rate_hz;
		if (!(t <= max_time_s + 1e-9)) break;
		const ChamberState st = profile.stateAt(t);
		const FogSample s = k == 0 ? sim.start(st, profile.initialState()) : sim.advance(dt, st);
		// gyro off: no gyro sample (an empty rate cell, as the drive writes); the thermistors keep logging
		f(t, s.power_on ? s.rate_dph : NAN, s.temp_C, st.table_rate_dph, st.field_uT, s.power_on ? 1.0 : 0.0);
	}
}

FogSeries chamberRunHeader(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings)
{
	FogSeries h = emptySimulatedSeries(device);
	const OptionalColumns c = optionalColumns(profile);
	if (c.table) h.table_rate_dph.assign(1, NAN);
	if (c.field) h.field_uT.assign(1, NAN);
	h.power.assign(1, NAN);
	recordSimMetadata(h, "chamber", profile, device, settings);
	return h;
}

FogSeries simulateChamber(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings)
{
	settings.validate();
	const auto n = static_cast<std::size_t>(std::floor(profile.duration_s() * settings.rate_hz + 1e-9)) + 1;
	const OptionalColumns c = optionalColumns(profile);
	FogSeries out = emptySimulatedSeries(device);
	out.time_s.reserve(n);
	auto& rate = out.rate_dph[2];
	rate.reserve(n);
	for (auto& col : out.temp_C) col.reserve(n);
	out.power.reserve(n);
	simulateChamberSamples(profile, device, settings, INFINITY,
						   [&](double t, double r, const std::vector<double>& temp_C, double table, double field, double power) {
							   out.time_s.push_back(t);
							   rate.push_back(r);
							   for (std::size_t i = 0; i < temp_C.size(); i++) out.temp_C[i].push_back(temp_C[i]);
							   out.power.push_back(power);
							   if (c.table) out.table_rate_dph.push_back(table);
							   if (c.field) out.field_uT.push_back(field);
						   });
	recordSimMetadata(out, "chamber", profile, device, settings);
	return out;
}

}  // namespace mrpt_fog::sim
