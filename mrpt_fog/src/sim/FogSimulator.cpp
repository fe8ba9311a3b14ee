/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::sim
{
namespace
{
constexpr double kArcsecPerDeg = 3600.0;
using mrpt_fog::units::kSecondsPerMinute;
constexpr double kSecondsPerDay = 86400.0;

// Rounds to a multiple of q; when 1/q is an integer (0.01 C) divides by it, so that the result
// is the double nearest to the decimal value (prints as "30.06", not "30.060000000000002").
double quantise(double v, double q)
{
	if (!(q > 0)) return v;
	const double inv = 1.0 / q;
	if (std::abs(inv - std::round(inv)) < 1e-9 * inv) return std::round(v * inv) / std::round(inv);
	return q * std::round(v / q);
}
}  // namespace

FogSimulator::FogSimulator(const FogDevice& device, const EffectSet& effects, std::uint64_t seed)
	: dev_(device),
	  effects_(effects),
	  thermal_((device.validate(), device.thermal)),
	  winding_(device.winding, device.thermal.layers, device.thermal.sectors),
	  rng_gyro_(seed, RandomStream::GyroNoise),
	  rng_therm_(seed, RandomStream::Thermistors),
	  rng_turn_on_(seed, RandomStream::TurnOn)
{
	for (const auto& id : effects_) on_[static_cast<std::size_t>(effectFromId(id))] = true;
}

void FogSimulator::drawTurnOn()
{
	// both drawn at every power-on, in this order, whatever is enabled (the offset of turn-on k
	// does not depend on whether the scale-factor repeatability is on)
	const double z_bias = rng_turn_on_.normal(), z_sf = rng_turn_on_.normal();
	turn_on_offset_dph_ = dev_.turn_on.bias_repeatability_dph * z_bias;
	turn_on_sf_ppm_ = dev_.turn_on.sf_repeatability_ppm * z_sf;
}

double FogSimulator::powerW(const ChamberState& s) const
{
	return (s.power_on && enabled(Effect::HeatSource)) ? dev_.thermal.electronics_power_W : 0.0;
}

double FogSimulator::nodeAt(const Eigen::VectorXd& T, CoilSide side, double angle_deg) const
{
	const int S = dev_.thermal.sectors;
	const int layer = side == CoilSide::Outer ? dev_.thermal.layers - 1 : 0;
	double x = std::fmod(angle_deg, 360.0);
	if (x < 0) x += 360.0;
	x *= S / 360.0;
	const int j0 = static_cast<int>(std::floor(x)) % S;
	const double f = x - std::floor(x);
	return (1 - f) * T(thermal_.coilNode(layer, j0)) + f * T(thermal_.coilNode(layer, (j0 + 1) % S));
}

FogSample FogSimulator::start(const ChamberState& s0, InitialThermalState init)
{
	state_ = s0;
	const bool cold = init == InitialThermalState::Cold;
	T_ = thermal_.steadyState(s0.air_C, cold ? 0.0 : powerW(s0));
	time_since_power_on_s_ = (cold && s0.power_on) ? 0.0 : std::numeric_limits<double>::infinity();
	run_time_s_ = 0;
	turn_on_offset_dph_ = turn_on_sf_ppm_ = 0;
	if (s0.power_on) drawTurnOn();
	therm_lag_C_.clear();
	for (const auto& t : dev_.thermistors) therm_lag_C_.push_back(nodeAt(T_, t.info.side, t.info.angle_deg));
	hysteresis_dph_ = 0;
	gm_bias_dph_ = dev_.noise.bias_instability_dph * rng_gyro_.normal();
	rrw_dph_ = 0;
	acc_deg_ = acc_ideal_deg_ = 0;
	q_prev_ = q_ideal_prev_ = 0;
	return makeSample(0.0, T_, s0, true);
}

FogSample FogSimulator::advance(double dt_s, const ChamberState& s1)
{
	if (!(dt_s > 0) || !std::isfinite(dt_s)) throw std::invalid_argument("FogSimulator::advance: dt must be > 0");
	const Eigen::VectorXd Tprev = T_;
	T_ = thermal_.step(T_, dt_s, state_.air_C, s1.air_C, powerW(state_), powerW(s1));
	run_time_s_ += dt_s;
	if (s1.power_on && !state_.power_on) drawTurnOn();
	if (s1.power_on && !state_.power_on) time_since_power_on_s_ = 0.0;
	else if (s1.power_on) time_since_power_on_s_ += dt_s;
	if (!s1.power_on) acc_deg_ = acc_ideal_deg_ = 0, q_prev_ = q_ideal_prev_ = 0;
	state_ = s1;
	return makeSample(dt_s, Tprev, s1, false);
}

FogSample FogSimulator::makeSample(double dt_s, const Eigen::VectorXd& Tprev, const ChamberState& s, bool first)
{
	const auto& e = dev_.errors;
	const int L = dev_.thermal.layers;
	FogSample out;
	out.power_on = s.power_on;
	out.coil_mean_C = T_.head(thermal_.coilNodeCount()).mean();
	out.inner_C = thermal_.layerMean_C(T_, 0);
	out.outer_C = thermal_.layerMean_C(T_, L - 1);

	// --- thermistors (lag with inputs linear over the step, exact first-order response)
	const bool lag = enabled(Effect::ThermistorLag);
	for (std::size_t i = 0; i < dev_.thermistors.size(); i++)
	{
		const auto& t = dev_.thermistors[i];
		const double x1 = nodeAt(T_, t.info.side, t.info.angle_deg);
		if (first || !lag || t.tau_s <= 0)
			therm_lag_C_[i] = x1;
		else
		{
			const double x0 = nodeAt(Tprev, t.info.side, t.info.angle_deg);
			const double r = dt_s / t.tau_s, one_minus_e = -std::expm1(-r);
			const double b = r < 1e-4 ? 0.5 * r : 1.0 - one_minus_e / r;  // weight of (x1 - x0)
			therm_lag_C_[i] = (1 - one_minus_e) * therm_lag_C_[i] + one_minus_e * x0 + b * (x1 - x0);
		}
		const double v = therm_lag_C_[i] + t.offset_C + dev_.thermistor_noise_C * rng_therm_.normal();
		out.temp_C.push_back(quantise(v, dev_.thermistor_quantum_C));
	}

	// --- noise (advanced every step, powered or not, so the realisation does not depend on power)
	const auto& nz = dev_.noise;
	double white_dph = 0;
	if (!first)
	{
		white_dph = 60.0 * nz.arw_deg_rt_h / std::sqrt(dt_s) * rng_gyro_.normal();
		const double a = std::exp(-dt_s / nz.bias_corr_time_s);
		gm_bias_dph_ = a * gm_bias_dph_ + nz.bias_instability_dph * std::sqrt(1 - a * a) * rng_gyro_.normal();
		rrw_dph_ += nz.rrw_deg_h_rt_h * std::sqrt(dt_s / units::kSecondsPerHour) * rng_gyro_.normal();
	}
	const double noise_dph = white_dph + gm_bias_dph_ + rrw_dph_;

	// --- thermal error terms [deg/h]
	double thermal = 0;
	const double dTin_out = out.inner_C - out.outer_C;
	if (!first)
	{
		const Eigen::VectorXd Tdot = (T_ - Tprev) / dt_s;
		if (enabled(Effect::ShupeRate)) out.shupe_dph = winding_.shupeRate_rad_s(Tdot) * units::kRadPerSecToDegPerHour;
		thermal += out.shupe_dph;
		if (enabled(Effect::GradientRate))
		{
			const double prev = thermal_.layerMean_C(Tprev, 0) - thermal_.layerMean_C(Tprev, L - 1);
			thermal += e.gradient_rate_dph_per_C_per_min() * (dTin_out - prev) / dt_s * kSecondsPerMinute;
		}
		if (enabled(Effect::Hysteresis))
		{
			const double dT = out.coil_mean_C - Tprev.head(thermal_.coilNodeCount()).mean();
			if (dT != 0)
			{
				const double target = (dT > 0 ? 0.5 : -0.5) * e.hysteresis_dph();
				hysteresis_dph_ = target + (hysteresis_dph_ - target) * std::exp(-std::abs(dT) / e.hysteresis_span_C);
			}
		}
	}
	if (enabled(Effect::Hysteresis)) thermal += hysteresis_dph_;
	// the additive terms of the registry (EffectRegistry.cpp), in its order
	const EffectTermInputs in{dTin_out, time_since_power_on_s_, s.field_uT, T_(thermal_.electronicsNode())};
	for (const auto& d : effectDescriptors())
	{
		if (!enabled(d.effect)) continue;
		if (d.bias_per_coefficient)
			thermal += e.coefficient(d.effect) * d.bias_per_coefficient(in, e);
		else if (d.add_bias_term_dph)
			d.add_bias_term_dph(in, e, thermal);
	}

	// --- applied rate and scale factor
	double applied_dph = s.table_rate_dph;
	if (enabled(Effect::EarthRate)) applied_dph += units::kEarthRate_dph * std::sin(dev_.latitude_deg * units::kDegToRad);
	double sf_error = 0;
	if (enabled(Effect::ScaleFactorTemp)) sf_error = e.sf_ppm_per_C() * 1e-6 * (out.coil_mean_C - e.sf_ref_C);
	thermal += sf_error * applied_dph;
	out.thermal_error_dph = thermal;

	const double ideal = applied_dph + noise_dph;
	double full = ideal + e.constant_bias_dph + thermal;
	if (dev_.turn_on.any())
	{
		constexpr double kDaysPerYear = 365.25;
		out.turn_on_bias_dph = turn_on_offset_dph_ + dev_.turn_on.aging_dph_per_year *
														 (dev_.turn_on.age_days + run_time_s_ / kSecondsPerDay) /
														 kDaysPerYear;
		out.turn_on_sf_ppm = turn_on_sf_ppm_;
		full += out.turn_on_bias_dph + turn_on_sf_ppm_ * 1e-6 * applied_dph;
	}
	if (!s.power_on)
	{
		out.rate_dph = out.ideal_rate_dph = 0;
		return out;
	}
	const double q_deg = nz.angle_quantum_arcsec / kArcsecPerDeg;
	if (first || q_deg <= 0)
	{
		out.rate_dph = full;
		out.ideal_rate_dph = ideal;
		return out;
	}
	// Quantise the accumulated angle (the FOG's digital output), not the rate.
	acc_deg_ += full * dt_s / units::kSecondsPerHour;
	acc_ideal_deg_ += ideal * dt_s / units::kSecondsPerHour;
	const long long q = std::llround(acc_deg_ / q_deg), qi = std::llround(acc_ideal_deg_ / q_deg);
	// counts x arcsec / s = deg/h
	out.rate_dph = static_cast<double>(q - q_prev_) * nz.angle_quantum_arcsec / dt_s;
	out.ideal_rate_dph = static_cast<double>(qi - q_ideal_prev_) * nz.angle_quantum_arcsec / dt_s;
	q_prev_ = q;
	q_ideal_prev_ = qi;
	return out;
}

}  // namespace mrpt_fog::sim
