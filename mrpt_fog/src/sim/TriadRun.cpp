/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/DriveTrajectory.h>
#include <mrpt_fog/sim/FogSimulator.h>
#include <mrpt_fog/sim/TriadRun.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_fog::sim
{
namespace
{
std::size_t idx(GyroAxis a) { return static_cast<std::size_t>(a); }
GyroAxis next(GyroAxis a, int k) { return static_cast<GyroAxis>((idx(a) + static_cast<std::size_t>(k)) % 3); }
std::string letter(GyroAxis a) { return std::string(1, axisLetter(a)); }

std::uint64_t mix64(std::uint64_t x)
{
	x += 0x9E3779B97F4A7C15ull;
	x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
	x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
	return x ^ (x >> 31);
}

/** Per sample: the means of sin and cos of the platform angle over the sample interval (the
 * first sample: at t = 0). */
struct PlatformTrig
{
	std::vector<double> mean_sin, mean_cos;
};

/** From angles that change linearly within each interval (a rate table: exact). */
PlatformTrig trigOfLinearAngles(const std::vector<double>& theta)
{
	PlatformTrig p;
	for (std::size_t k = 0; k < theta.size(); k++)
	{
		const double a0 = k == 0 ? theta[0] : theta[k - 1], a1 = theta[k], d = a1 - a0;
		const bool small = std::abs(d) < 1e-9;
		p.mean_sin.push_back(small ? std::sin(0.5 * (a0 + a1)) : (std::cos(a0) - std::cos(a1)) / d);
		p.mean_cos.push_back(small ? std::cos(0.5 * (a0 + a1)) : (std::sin(a1) - std::sin(a0)) / d);
	}
	return p;
}

struct AxisRates
{
	std::vector<double> rate_dph, ideal_dph;
};

/** A horizontal axis over the profile's states: applied rate = its Earth-rate projection at the
 * platform angles (the table or vehicle turns about the up axis, not about it). */
AxisRates simulateHorizontalAxis(const ChamberProfile& profile, const FogDevice& dev, const SimSettings& settings,
								 std::uint64_t seed, const PlatformTrig& trig, bool north_at_zero)
{
	EffectSet effects = settings.effects;
	const bool earth = effects.erase("earth_rate") > 0;  // applied here, on the horizontal projection
	const double omega_h_dph = earth ? units::kEarthRate_dph * std::cos(dev.latitude_deg * units::kDegToRad) : 0.0;
	FogSimulator sim(dev, effects, seed);
	const double dt = 1.0 / settings.rate_hz;
	AxisRates out;
	const std::size_t n = trig.mean_sin.size();
	out.rate_dph.reserve(n);
	out.ideal_dph.reserve(n);
	for (std::size_t k = 0; k < n; k++)
	{
		const double t = static_cast<double>(k) / settings.rate_hz;
		ChamberState st = profile.stateAt(t);
		st.table_rate_dph = omega_h_dph * (north_at_zero ? trig.mean_cos[k] : trig.mean_sin[k]);
		st.field_uT = 0;  // the profile's field is axial (along the up axis)
		const FogSample s = k == 0 ? sim.start(st, profile.initialState()) : sim.advance(dt, st);
		out.rate_dph.push_back(s.rate_dph);
		out.ideal_dph.push_back(s.ideal_rate_dph);
	}
	return out;
}

/** Metadata of the triad: mount, per-axis device differences and seeds, constant Earth rates. */
void recordTriadMetadata(FogSeries& s, const FogDevice& device, const SimSettings& settings, GyroAxis up,
						 bool platform_turns)
{
	const GyroAxis east = next(up, 1), north = next(up, 2);
	s.setMetadata("triad.up_axis", letter(up));
	s.setMetadata("triad.mount", letter(east) + " east, " + letter(north) + " north, " + letter(up) +
									 " up at platform angle 0 (level; the platform turns about " + letter(up) + ")");
	s.setMetadata("table_axis", letter(up));
	s.setMetadata("triad.model",
				  "one thermal network and one thermistor set for the three coils; per-axis error sensitivities and "
				  "noise seeds (docs/reference/simulator.md, Three-axis FOG)");
	const bool earth = settings.effects.count("earth_rate") > 0;
	const double lat = device.latitude_deg * units::kDegToRad;
	const double up_dph = earth ? units::kEarthRate_dph * std::sin(lat) : 0.0;
	s.setMetadata("earth_rate_dph." + letter(up), formatValue("%.17g", up_dph));
	if (!platform_turns)
	{
		s.setMetadata("earth_rate_dph." + letter(east), "0");
		s.setMetadata("earth_rate_dph." + letter(north),
					  formatValue("%.17g", earth ? units::kEarthRate_dph * std::cos(lat) : 0.0));
	}
	const auto base = device.describe();
	for (GyroAxis a : {GyroAxis::X, GyroAxis::Y, GyroAxis::Z})
	{
		s.setMetadata("sim.triad." + letter(a) + ".seed", std::to_string(triadAxisSeed(settings.seed, a)));
		const auto d = triadAxisDevice(device, a).describe();
		for (std::size_t i = 0; i < d.size() && i < base.size(); i++)
			if (d[i].second != base[i].second) s.setMetadata("sim.triad." + letter(a) + "." + d[i].first, d[i].second);
	}
}

/** Every sample's platform angle [rad] from the mean table rates of a chamber profile. */
std::vector<double> tableAngles(const ChamberProfile& profile, double rate_hz, std::size_t n)
{
	std::vector<double> theta(n, 0.0);
	const double dt = 1.0 / rate_hz;
	for (std::size_t k = 1; k < n; k++)
		theta[k] = theta[k - 1] + profile.stateAt(static_cast<double>(k) / rate_hz).table_rate_dph * dt *
									  units::kDegPerHourToRadPerSec;
	return theta;
}
}  // namespace

FogDevice triadAxisDevice(const FogDevice& device, GyroAxis axis)
{
	FogDevice d = device;
	if (axis == GyroAxis::Z) return d;
	const bool x = axis == GyroAxis::X;
	d.name = device.name + (x ? " (triad x coil)" : " (triad y coil)");
	d.winding.midpoint_offset_m = device.winding.midpoint_offset_m * (x ? -0.6 : 1.3);
	d.errors.radial_gradient_dph_per_C() = device.errors.radial_gradient_dph_per_C() * (x ? 0.7 : 1.3);
	d.errors.sf_ppm_per_C() = x ? 14.0 : 27.0;
	d.errors.constant_bias_dph = x ? -0.2 : 0.45;
	return d;
}

std::uint64_t triadAxisSeed(std::uint64_t seed, GyroAxis axis)
{
	if (axis == GyroAxis::Z) return seed;
	return mix64(seed ^ mix64(0x7472696164ull + idx(axis)));  // "triad" + axis
}

FogSeries simulateTriadChamber(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings,
							   GyroAxis up)
{
	SimSettings up_settings = settings;
	up_settings.seed = triadAxisSeed(settings.seed, up);
	FogSeries s = simulateChamber(profile, triadAxisDevice(device, up), up_settings);
	// simulateChamber writes the z column: it is the up axis'
	if (up != GyroAxis::Z) std::swap(s.rate_dph[2], s.rate_dph[idx(up)]);
	const std::size_t n = s.size();
	const std::vector<double> theta = tableAngles(profile, settings.rate_hz, n);
	bool turns = false;
	for (double a : theta) turns |= a != 0.0;
	const PlatformTrig trig = trigOfLinearAngles(theta);
	for (int k : {1, 2})
	{
		const GyroAxis a = next(up, k);
		AxisRates r = simulateHorizontalAxis(profile, triadAxisDevice(device, a), settings, triadAxisSeed(settings.seed, a),
											 trig, k == 2);
		s.rate_dph[idx(a)] = std::move(r.rate_dph);
	}
	// no gyro sample where the gyro is off (an empty rate on every axis, as the drive writes)
	for (std::size_t k = 0; k < n; k++)
		if (!s.gyroOn(k))
			for (auto& r : s.rate_dph) r[k] = NAN;
	s.has_axis = {true, true, true};
	// the single-axis metadata describe the up axis' run; the run seed is the triad's
	s.setMetadata("sim.seed", std::to_string(settings.seed));
	s.setMetadata("sim.scenario", "chamber (three-axis FOG)");
	recordTriadMetadata(s, device, settings, up, turns);
	s.validate();
	return s;
}

DriveOutput simulateTriadDrive(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
							   const OdometryErrors& odo)
{
	DriveOutput out = simulateDrive(cabin, device, settings, odo);
	const std::size_t n = out.fog.size();
	const DriveTrajectory traj = DriveTrajectory::randomDrive(settings.seed, cabin.duration_s());
	// The heading is not linear within a sample interval (turn entries): the means of sin and cos
	// by a 32-point midpoint rule on the exact trajectory.
	PlatformTrig trig;
	constexpr int kPoints = 32;
	for (std::size_t k = 0; k < n; k++)
	{
		const double t1 = out.fog.time_s[k], t0 = k == 0 ? t1 : out.fog.time_s[k - 1];
		double ms = 0, mc = 0;
		for (int j = 0; j < kPoints; j++)
		{
			const double yaw = traj.at(t0 + (j + 0.5) * (t1 - t0) / kPoints).yaw_rad;
			ms += std::sin(yaw), mc += std::cos(yaw);
		}
		trig.mean_sin.push_back(ms / kPoints);
		trig.mean_cos.push_back(mc / kPoints);
	}
	for (int k : {1, 2})
	{
		const GyroAxis a = next(GyroAxis::Z, k);
		AxisRates r =
			simulateHorizontalAxis(cabin, triadAxisDevice(device, a), settings, triadAxisSeed(settings.seed, a), trig, k == 2);
		out.fog.rate_dph[idx(a)] = std::move(r.rate_dph);
		out.fog_ideal.rate_dph[idx(a)] = std::move(r.ideal_dph);
	}
	for (FogSeries* f : {&out.fog, &out.fog_ideal})
	{
		// no gyro sample where the gyro is off (an empty rate, as simulateDrive writes)
		for (std::size_t k = 0; k < f->size(); k++)
			if (!f->gyroOn(k))
				for (auto& r : f->rate_dph) r[k] = NAN;
		f->has_axis = {true, true, true};
		f->setMetadata("sim.scenario", "vehicle (three-axis FOG)");
		recordTriadMetadata(*f, device, settings, GyroAxis::Z, true);
		f->validate();
	}
	out.fog_ideal.setMetadata("sim.effects", "none (ideal twin of FOG: same noise realisation)");
	const auto ideal_obs = observationsFromSeries(out.fog_ideal);
	if (out.others.size() != 3 * n) throw std::logic_error("simulateTriadDrive: unexpected stream layout");
	for (std::size_t k = 0; k < n; k++) out.others[3 * k] = ideal_obs[k];
	return out;
}

}  // namespace mrpt_fog::sim
