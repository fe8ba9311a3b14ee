/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogSimulator.h
 * One simulated FOG stepped through time: the coil thermal network (CoilThermalModel), the
 * Shupe integral over the winding (CoilWinding), the other error sources (ErrorEffects.h), the
 * thermistors and the gyro noise. The chamber runner and the vehicle scenario both drive it.
 *
 * Output convention: the gyro sample at t_{k+1} is the mean rate over (t_k, t_{k+1}] (a FOG
 * reports integrated angle per sample period); so the Shupe term uses the node temperature
 * change over the step divided by dt (exact for that mean). Each sample carries two rates drawn
 * from the SAME noise realisation: `rate_dph` (all enabled errors) and `ideal_rate_dph`
 * (no thermal error, nominal scale factor, no constant bias; the vehicle scenario's FOG_IDEAL).
 * While the gyro is unpowered both rates are 0 and power_on is false.
 * Turn-on repeatability and aging (FogDevice::turn_on, off by default): at each power-on an
 * offset and a scale-factor error are drawn from their own random stream (RandomStream::TurnOn,
 * so the other streams do not change), and the bias drifts with the device's age
 * (age_days + t); both enter `rate_dph` only, like the constant bias. */

#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/CoilThermalModel.h>
#include <mrpt_fog/sim/CoilWinding.h>
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/ErrorEffects.h>
#include <mrpt_fog/sim/FogDevice.h>
#include <mrpt_fog/sim/SimRandom.h>

#include <Eigen/Dense>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace mrpt_fog::sim
{
/** One output sample and some internal truth (for diagnostics and tests). */
struct FogSample
{
	double rate_dph = 0;  //!< gyro output with all enabled errors [deg/h]
	double ideal_rate_dph = 0;  //!< same noise, no thermal error [deg/h]
	std::vector<double> temp_C;  //!< thermistor readings [degC], device order
	bool power_on = true;
	// truth
	double coil_mean_C = 0;  //!< mean of all winding nodes [degC]
	double inner_C = 0;  //!< inner layer mean [degC]
	double outer_C = 0;  //!< outer layer mean [degC]
	double shupe_dph = 0;  //!< Shupe term this step [deg/h]
	double thermal_error_dph = 0;  //!< rate_dph - ideal_rate_dph before quantisation [deg/h], without turn_on_bias_dph
	/** Turn-on offset drawn at the last power-on plus the aging drift at this time [deg/h], and
	 * the scale-factor error drawn at the last power-on [ppm] (FogDevice::turn_on; 0 when off). */
	double turn_on_bias_dph = 0, turn_on_sf_ppm = 0;
};

class FogSimulator
{
   public:
	FogSimulator(const FogDevice& device, const EffectSet& effects, std::uint64_t seed);

	/** Initialises the thermal state for conditions s0 (Steady: equilibrium including the
	 * electronics power if on; Cold: unpowered equilibrium, and a power-on at t = 0 starts the
	 * warm-up) and returns the t = 0 sample (zero temperature rate). */
	FogSample start(const ChamberState& s0, InitialThermalState init);

	/** Advances by dt_s to conditions s1 (air temperature varies linearly over the step; power,
	 * field and table rate take s1's values, table_rate_dph being the MEAN applied rate over the
	 * step). Throws std::invalid_argument if dt_s <= 0. */
	FogSample advance(double dt_s, const ChamberState& s1);

	const CoilThermalModel& thermal() const { return thermal_; }
	const CoilWinding& winding() const { return winding_; }
	const Eigen::VectorXd& nodeTemperatures_C() const { return T_; }
	const FogDevice& device() const { return dev_; }
	bool enabled(Effect effect) const { return on_[static_cast<std::size_t>(effect)]; }

   private:
	double powerW(const ChamberState& s) const;
	double nodeAt(const Eigen::VectorXd& T, CoilSide side, double angle_deg) const;
	FogSample makeSample(double dt_s, const Eigen::VectorXd& Tprev, const ChamberState& s, bool first);

	FogDevice dev_;
	EffectSet effects_;
	std::array<bool, kEffectCount> on_{};  //!< effects_ by enumerator (no set search per sample)
	CoilThermalModel thermal_;
	CoilWinding winding_;
	SimRandom rng_gyro_, rng_therm_;

	Eigen::VectorXd T_;
	ChamberState state_;
	std::vector<double> therm_lag_C_;
	double hysteresis_dph_ = 0;
	double time_since_power_on_s_ = std::numeric_limits<double>::infinity();
	double gm_bias_dph_ = 0, rrw_dph_ = 0;
	SimRandom rng_turn_on_;
	double turn_on_offset_dph_ = 0, turn_on_sf_ppm_ = 0;  //!< drawn at the last power-on
	double run_time_s_ = 0;  //!< since start() (for the aging drift)
	void drawTurnOn();
	double acc_deg_ = 0, acc_ideal_deg_ = 0;
	long long q_prev_ = 0, q_ideal_prev_ = 0;
};

}  // namespace mrpt_fog::sim
