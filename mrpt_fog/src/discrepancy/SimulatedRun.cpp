/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/SimulatedRun.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
using mrpt_fog::units::kNaN;

sim::ChamberProfile loadProfile(const std::string& name)
{
	const auto presets = sim::ChamberProfile::presetNames();
	if (std::find(presets.begin(), presets.end(), name) != presets.end()) return sim::ChamberProfile::preset(name);
	if (std::filesystem::exists(name)) return sim::ChamberProfile::fromFile(name);
	throw std::invalid_argument("chamber profile '" + name + "' is neither a built-in profile nor a readable file");
}

double medianStep(const std::vector<double>& t)
{
	std::vector<double> d;
	for (std::size_t k = 1; k < t.size(); ++k) d.push_back(t[k] - t[k - 1]);
	if (d.empty()) throw std::invalid_argument("run has fewer than two samples");
	std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
	return d[d.size() / 2];
}
}  // namespace

std::size_t ChamberDrive::steps() const
{
	if (source == DriveSource::MeasuredLog) return log_states.size();
	return static_cast<std::size_t>(std::floor(profile.duration_s() * rate_hz + 1e-9)) + 1;
}

sim::ChamberState ChamberDrive::stateAt(std::size_t step) const
{
	if (source == DriveSource::MeasuredLog) return log_states.at(step);
	return profile.stateAt(static_cast<double>(step) / rate_hz);
}

sim::InitialThermalState ChamberDrive::initialState() const
{
	return source == DriveSource::MeasuredLog ? sim::InitialThermalState::Steady : profile.initialState();
}

namespace
{
/** Power, table rate and field per simulator step from the run's columns (held). */
ChamberDrive driveFromLog(const FogSeries& run)
{
	ChamberDrive d;
	d.source = DriveSource::MeasuredLog;
	const double dt = medianStep(run.time_s);
	if (!(dt > 0)) throw std::invalid_argument("run time step is not positive");
	d.rate_hz = 1.0 / dt;
	const double t0 = run.time_s.front();
	d.sim_index.resize(run.size());
	for (std::size_t k = 0; k < run.size(); ++k)
	{
		const double idx = std::round((run.time_s[k] - t0) * d.rate_hz);
		d.sim_index[k] = static_cast<std::size_t>(std::max(0.0, idx));
	}
	const std::size_t nSim = d.sim_index.back() + 1;
	if (nSim > 50'000'000) throw std::invalid_argument("run too long for the simulator grid of its median sample period");
	d.log_states.assign(nSim, sim::ChamberState{});
	std::size_t k = 0;
	sim::ChamberState cur;
	for (std::size_t j = 0; j < nSim; ++j)
	{
		while (k < run.size() && d.sim_index[k] <= j)
		{
			if (run.power.size() == run.size() && std::isfinite(run.power[k])) cur.power_on = run.power[k] >= 0.5;
			if (run.table_rate_dph.size() == run.size() && std::isfinite(run.table_rate_dph[k])) cur.table_rate_dph = run.table_rate_dph[k];
			if (run.field_uT.size() == run.size() && std::isfinite(run.field_uT[k])) cur.field_uT = run.field_uT[k];
			++k;
		}
		d.log_states[j] = cur;
	}
	return d;
}

void reconstructInto(ChamberDrive& d, const SimModel& model, const FogSeries& run, const AirReconstructionOptions& opt = {})
{
	d.air = reconstructChamberAir(model.device, model.effects, model.thermal_time_scale, d.log_states, d.rate_hz, run,
								  d.sim_index, opt);
	for (std::size_t j = 0; j < d.log_states.size(); ++j) d.log_states[j].air_C = d.air.airAt(static_cast<double>(j) / d.rate_hz);
	d.how = "the measured log: power, table rate and field from its columns; chamber air reconstructed from the "
			"thermistors through the thermal network (" +
			std::to_string(d.air.knot_time_s.size()) + " knots every " + formatValue("%.2g", d.air.knot_time_s.size() > 1 ? d.air.knot_time_s[1] : 0) +
			" s, thermistor fit RMS " + formatValue("%.2g", d.air.fit_rms_C) + " C, air 95 % half-width " + formatValue("%.2g", d.air.mean_ci95_half_C) +
			" C mean, " + formatValue("%.2g", d.air.max_ci95_half_C) + " C max)";
}
}  // namespace

ChamberDrive chamberDriveForRun(const FogSeries& run, const SimulatorConfig& cfg)
{
	ChamberDrive d;
	std::string name = cfg.profile;
	if (!name.empty())
		d.how = "profile '" + name + "' given in " + cfg.source;
	else
	{
		name = run.metadataValue("sim.profile");
		if (name.empty())
		{
			if (run.size() < 2) throw std::invalid_argument("run has fewer than two samples");
			d = driveFromLog(run);
			reconstructInto(d, simModelFromConfig(cfg), run);
			return d;
		}
		d.how = "profile '" + name + "' from the run's metadata sim.profile";
	}
	d.profile = loadProfile(name);
	// The profile's grid step from the whole run: the median single step carries the time
	// stamps' rounding (ulps of a time read from text or from 100 ns ticks), which over 1e5
	// samples put the last one a 1e-3 step off the grid (10 Hz logs with --block-s 0).
	const double dt_median = medianStep(run.time_s);
	if (!(dt_median > 0)) throw std::invalid_argument("run time step is not positive");
	const double span_s = run.time_s.back() - run.time_s.front();
	const double steps = std::round(span_s / dt_median);
	const double dt = steps >= 1 ? span_s / steps : dt_median;
	d.rate_hz = 1.0 / dt;
	const double last = std::floor(d.profile.duration_s() * d.rate_hz + 1e-9);
	d.sim_index.resize(run.size());
	for (std::size_t k = 0; k < run.size(); ++k)
	{
		const double x = run.time_s[k] * d.rate_hz;
		const double idx = std::round(x);
		if (std::abs(x - idx) > 1e-3 || idx < 0 || idx > last)
			throw std::invalid_argument("run sample " + std::to_string(k) + " (t = " + std::to_string(run.time_s[k]) +
										" s) is not on the " + std::to_string(dt) + " s grid of profile '" + name +
										"' (duration " + std::to_string(d.profile.duration_s()) + " s)");
		d.sim_index[k] = static_cast<std::size_t>(idx);
		if (run.power.size() == run.size())
		{
			const bool on = d.profile.stateAt(idx / d.rate_hz).power_on;
			if (on != (run.power[k] >= 0.5))
				throw std::invalid_argument("the run's power column disagrees with profile '" + name + "' at t = " +
											std::to_string(run.time_s[k]) + " s: not the profile this run followed");
		}
	}
	return d;
}

ChamberDrive reconstructDriveWith(const ChamberDrive& drive, const SimModel& model, const FogSeries& run,
								  const AirReconstructionOptions& opt)
{
	if (drive.source != DriveSource::MeasuredLog) return drive;
	ChamberDrive d = drive;
	reconstructInto(d, model, run, opt);
	return d;
}

SimModel simModelFromConfig(const SimulatorConfig& cfg)
{
	SimModel m;
	m.device = cfg.device;
	m.effects = cfg.effects;
	return m;
}

SimTrace simulateOnRun(const SimModel& model, const ChamberDrive& drive, const FogSeries& run)
{
	sim::FogDevice dev = model.device.withoutNoise();
	const double s = model.thermal_time_scale;
	dev.thermal.scaleHeatCapacities(s);

	std::vector<int> devIndex;
	for (const auto& th : run.thermistors)
	{
		int found = -1;
		for (std::size_t j = 0; j < dev.thermistors.size(); ++j)
			if (dev.thermistors[j].info.name == th.name) found = static_cast<int>(j);
		if (found < 0)
			throw std::invalid_argument("run thermistor '" + th.name + "' is not a thermistor of the simulated device");
		devIndex.push_back(found);
	}
	// Stepped exactly as sim::simulateChamber steps it (same grid, same start), noise off; the
	// simulator is driven directly to read the electronics node as well.
	sim::FogSimulator fog(dev, model.effects, 1);
	const double dt = 1.0 / drive.rate_hz;
	const std::size_t nSim = drive.steps();
	const std::size_t n = run.size();
	// run samples per simulator sample (a run sample maps to one simulator sample)
	std::vector<std::vector<std::size_t>> atSim(nSim);
	for (std::size_t k = 0; k < n; ++k)
		if (drive.sim_index[k] < nSim) atSim[drive.sim_index[k]].push_back(k);

	SimTrace tr;
	tr.bias_dph.assign(n, kNaN);
	tr.electronics_C.assign(n, kNaN);
	tr.temp_C.assign(run.thermistorCount(), std::vector<double>(n, kNaN));
	const int eNode = fog.thermal().electronicsNode();
	for (std::size_t j = 0; j < nSim; ++j)
	{
		const sim::ChamberState st = drive.stateAt(j);
		const sim::FogSample s = j == 0 ? fog.start(st, drive.initialState()) : fog.advance(dt, st);
		for (std::size_t k : atSim[j])
		{
			if (s.power_on) tr.bias_dph[k] = s.rate_dph - st.table_rate_dph;
			tr.electronics_C[k] = fog.nodeTemperatures_C()(eNode);
			for (std::size_t i = 0; i < devIndex.size(); ++i) tr.temp_C[i][k] = s.temp_C[static_cast<std::size_t>(devIndex[i])];
		}
	}
	return tr;
}

std::string ParamSlot::label() const
{
	const auto* d = sim::descriptorOfCalibrationParameter(id);
	if (id == "thermistor_offsets_C" || (d && d->calibration.indexed)) return id + "[" + std::to_string(index) + "]";
	return id;
}

std::vector<ParamSlot> expandSlots(const std::vector<std::string>& free, const SimModel& m)
{
	std::vector<ParamSlot> out;
	auto effectOn = [&](const std::string& id)
	{
		if (id == "sf_ref_C") return m.effects.count("scale_factor_temp") > 0;  // the scale factor's reference
		for (const auto& e : sim::allEffectIds())
			if (coefficientParameterOf(e) == id) return m.effects.count(e) > 0;
		return true;  // constant, scale, offsets
	};
	for (const auto& id : free)
	{
		if (!effectOn(id)) continue;
		const auto* d = sim::descriptorOfCalibrationParameter(id);
		if (d && d->calibration.indexed)
			for (std::size_t i = 0; i < sim::calibrationSlotCount(*d, m.device); ++i) out.push_back({id, static_cast<int>(i)});
		else if (id == "thermistor_offsets_C")
			for (std::size_t i = 0; i < m.device.thermistors.size(); ++i) out.push_back({id, static_cast<int>(i)});
		else
			out.push_back({id, 0});
	}
	return out;
}

namespace
{
double* slotRef(SimModel& m, const ParamSlot& s)
{
	if (s.id == "constant_bias_dph") return &m.device.errors.constant_bias_dph;
	if (s.id == "sf_ref_C") return &m.device.errors.sf_ref_C;
	if (s.id == "thermal_time_scale") return &m.thermal_time_scale;
	if (s.id == "thermistor_offsets_C") return &m.device.thermistors.at(static_cast<std::size_t>(s.index)).offset_C;
	// an effect's calibration parameter (the effect registry says where it lives)
	if (const auto* d = sim::descriptorOfCalibrationParameter(s.id))
		if (double* slot = sim::calibrationSlot(*d, m.device, static_cast<std::size_t>(s.index))) return slot;
	throw std::invalid_argument("unknown free parameter '" + s.id + "'");
}
}  // namespace

double getParam(const SimModel& m, const ParamSlot& s) { return *slotRef(const_cast<SimModel&>(m), s); }

void setParam(SimModel& m, const ParamSlot& s, double v)
{
	if (const auto* d = sim::descriptorOfCalibrationParameter(s.id); d && std::isfinite(d->calibration.min_value))
		v = std::max(v, d->calibration.min_value);
	if (s.id == "thermal_time_scale") v = std::clamp(v, 0.2, 5.0);
	*slotRef(m, s) = v;
}

}  // namespace mrpt_fog::discrepancy
