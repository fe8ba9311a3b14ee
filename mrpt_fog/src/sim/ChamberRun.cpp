/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

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
	std::ostringstream rate;
	rate.precision(10);
	rate << settings.rate_hz;
	series.setMetadata("sim.generator", "fog-sim (mrpt_fog simulator v1)");
	series.setMetadata("sim.scenario", scenario);
	series.setMetadata("sim.profile", settings.profile_source.empty() ? profile.name() : settings.profile_source);
	series.setMetadata("sim.profile_name", profile.name());
	series.setMetadata("sim.seed", std::to_string(settings.seed));
	series.setMetadata("sim.rng", "mt19937_64 + splitmix64 streams + Box-Muller");
	series.setMetadata("sim.rate_hz", rate.str());
	series.setMetadata("sim.effects", effectsToString(settings.effects));
	std::ostringstream lat;
	lat.precision(10);
	lat << device.latitude_deg;
	series.setMetadata("latitude_deg", lat.str());
	for (const auto& kv : device.describe()) series.setMetadata("sim." + kv.first, kv.second);
	// A run that starts cold and powered is a turn-on at t = 0 (the simulator's warm-up clock
	// starts there): said for the compensator's and the warm-up fit's turn-on bookkeeping.
	if (profile.initialState() == InitialThermalState::Cold && profile.stateAt(0.0).power_on)
		series.setMetadata("power_on_time_s", "0");
}

FogSeries simulateChamber(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings)
{
	settings.validate();
	FogSimulator sim(device, settings.effects, settings.seed);
	const double dt = 1.0 / settings.rate_hz;
	const auto n = static_cast<std::size_t>(std::floor(profile.duration_s() * settings.rate_hz + 1e-9)) + 1;

	bool uses_table = false, uses_field = false;
	for (const auto& s : profile.segments())
	{
		if (s.kind == ProfileSegment::Kind::Table && s.value != 0) uses_table = true;
		if (s.kind == ProfileSegment::Kind::Field && s.value != 0) uses_field = true;
	}

	FogSeries out;
	out.sensor_label = "FOG";
	out.epoch_s = kSimEpoch_s;
	out.has_axis = {false, false, true};
	for (const auto& t : device.thermistors) out.thermistors.push_back(t.info);
	out.time_s.reserve(n);
	auto& rate = out.rate_dph[2];
	rate.reserve(n);
	out.temp_C.assign(device.thermistors.size(), {});
	for (auto& c : out.temp_C) c.reserve(n);
	out.power.reserve(n);

	for (std::size_t k = 0; k < n; k++)
	{
		const double t = static_cast<double>(k) / settings.rate_hz;
		const ChamberState st = profile.stateAt(t);
		const FogSample s = k == 0 ? sim.start(st, profile.initialState()) : sim.advance(dt, st);
		out.time_s.push_back(t);
		rate.push_back(s.rate_dph);
		for (std::size_t i = 0; i < s.temp_C.size(); i++) out.temp_C[i].push_back(s.temp_C[i]);
		out.power.push_back(s.power_on ? 1.0 : 0.0);
		if (uses_table) out.table_rate_dph.push_back(st.table_rate_dph);
		if (uses_field) out.field_uT.push_back(st.field_uT);
	}
	recordSimMetadata(out, "chamber", profile, device, settings);
	return out;
}

}  // namespace mrpt_fog::sim
