/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file Compensator.h
 * Real-time thermal-bias compensation, sample by sample, causal, O(1) per sample:
 *   compensated_dph = raw_dph - bias_dph(temperatures, causal rates)
 * and, when the calibration has them (CalibrationYaml.h, version 2), a warm-up term in the bias
 * and the scale factor versus temperature:
 *   bias_dph += warmup(t - t_on)   (from a known turn-on t_on on: notePowerOn)
 *   compensated_dph = (raw_dph - bias_dph) / (1 + 1e-6 s_ppm(T))
 * with T the scale-factor thermistor's current reading (clamped to its calibrated range; while
 * it is missing the last valid s is held, before any valid reading s at the range centre),
 * and, when the calibration has a magnetic section (version 3, MagneticModel.h), the Faraday term
 *   bias_dph += dph_per_uT * B_uT
 * with B_uT the applied axial field given by noteField() (not a thermistor: its own input, held
 * until the next call; while it is unknown no field term is added and the sample is counted in
 * CompensationCounters::field_unknown_samples).
 * Without those sections the per-sample work is one extra predictable branch.
 *
 * Rates come from the causal estimator recorded in the calibration (a calibration fitted with
 * the non-causal "savgol" estimator is refused: it cannot run in real time). Each model is
 * compiled into one polynomial per signal, grouped by signal kind. At most 32
 * thermistors.
 *
 * Per sample:
 *  - a thermistor is "missing" when its reading is NaN or its rate has no estimate yet (< 2
 *    valid samples in the window). The main model is used unless it reads a missing
 *    thermistor; then the fallback fitted without that thermistor, if that fallback reads no
 *    other missing one (flag Fallback); else the mean calibration bias only (flag NoModel).
 *    When the thermistor returns (reading and rate available again: after a dropout longer
 *    than the window that is its second valid sample) the main model is used again.
 *  - a signal outside its calibrated range is handled by the calibration's extrapolation
 *    policy (Calibration.h: clamp, or the default linear continuation along the edge tangent;
 *    flag Clamped, counted with the largest excursion seen): a polynomial of order > 1 is never
 *    extrapolated as such. The kernel clamps; the linear part is added on the rare path.
 *  - start-up: while a rate the main model reads is not yet estimable or its window
 *    covers less than half its length (start of the log, each burst, after a gap), the
 *    calibration's rate-free start-up model is used when it has one and every temperature it
 *    reads is present (flag RateFree, Output::model kStartupModel). A model that reads no
 *    rate never waits for one: a missing rate is "missing" only for a model that reads it.
 *  - RateWarmup: the model in use reads a rate whose window covers less than half its length
 *    (calibrations without a start-up model, or a fallback during a dropout).
 *  - lag signals (dTlag/dt(a,tau), LagFilter.h): a first-order lag of each reading they need,
 *    carried from sample to sample, warm-started equal to the first valid reading; a lag signal
 *    is missing exactly when its thermistor's reading is (it needs no rate window).
 *  - hysteresis signals (hyst(a,play|branch,w), HysteresisFilter.h): the operator of each reading
 *    they need, carried from sample to sample, warm-started at the first valid reading (output
 *    0); missing exactly when its thermistor's reading is; a dropout holds the state.
 * The lag and hysteresis state is updated out of line, only when some model reads such a signal.
 * Batch compensate() is exactly the streaming loop, so batch == streaming by construction; the
 * tests also check it against an independent evaluation of the fitted feature set.
 *
 * Construction throws std::invalid_argument when the series layout does not match the
 * calibration (a thermistor missing, or at another side/angle; the message lists both).
 */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/HysteresisFilter.h>
#include <mrpt_fog/model/LagFilter.h>
#include <mrpt_fog/model/RateEstimator.h>
#include <mrpt_fog/obs/FogRun.h>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** Bits of Compensator::Output::flags (why a sample's bias is not the main model's alone). */
enum CompensationFlag : std::uint8_t
{
	Fallback = 1,
	NoModel = 2,
	Clamped = 4,
	RateWarmup = 8,
	/** The rate-free start-up model (Calibration::startup) is in use: a rate the main model reads is
	 * not yet estimable or its window covers less than half its length (start, burst, gap). */
	RateFree = 16
};

struct CompensationCounters
{
	std::size_t samples = 0;
	std::size_t fallback_samples = 0;
	std::size_t no_model_samples = 0;
	std::size_t clamped_samples = 0;  //!< samples with at least one clamped signal
	std::size_t clamped_signals = 0;  //!< total clamped signal values
	std::size_t temp_outside_samples = 0;  //!< samples with a temperature or difference outside its range
	std::size_t rate_outside_samples = 0;  //!< samples with a rate outside its range
	double max_temp_excursion_C = 0;  //!< largest distance of a temperature/difference beyond its range [degC]
	double max_rate_excursion_C_per_s = 0;  //!< largest distance of a rate beyond its range [degC/s]
	std::size_t warmup_samples = 0;
	std::size_t rate_free_samples = 0;  //!< samples compensated by the rate-free start-up model
	std::size_t model_switches = 0;  //!< changes of the model in use
	/** Samples without a known applied field (noteField never called, or NaN) while the
	 * calibration has a magnetic section: compensated without the field term. */
	std::size_t field_unknown_samples = 0;
	/** Samples whose applied field lies outside the calibration's recorded field range
	 * (MagneticModel::field_min_uT..field_max_uT): the term is extrapolated there. */
	std::size_t field_outside_samples = 0;
	double max_field_excursion_uT = 0;  //!< largest distance of the field beyond that range [uT]
};

/** Which build of the per-sample code a Compensator runs. Both give bitwise the same numbers
 * (tests/model/test_Compensator.cpp checks it); AVX2 is faster. */
enum class KernelBuild
{
	Auto,  //!< AVX2 when the CPU has it and the layout has 1..4 thermistors, else portable
	Portable,  //!< baseline x86-64 (SSE2), or the target's generic vectors elsewhere
	Avx2  //!< AVX2; the constructor throws std::invalid_argument if the CPU lacks it
};

class Compensator
{
   public:
	/** Output::model while the rate-free start-up model is in use. */
	static constexpr int kStartupModel = -2;
	/** layout: the thermistors of the series to be compensated, in its column order. */
	Compensator(const Calibration& cal, const std::vector<ThermistorInfo>& layout, KernelBuild build = KernelBuild::Auto);
	~Compensator();
	Compensator(const Compensator&);
	Compensator(Compensator&&) noexcept;
	Compensator& operator=(const Compensator&);
	Compensator& operator=(Compensator&&) noexcept;

	struct Output
	{
		double bias_dph = 0;
		double compensated_dph = 0;
		std::uint8_t flags = 0;
		int model = 0;  //!< 0 main, 1 + i fallback i, -1 no model, kStartupModel the rate-free start-up model
	};
	/** One sample: time [s] strictly increasing, raw gyro rate [deg/h], temperatures [degC] in
	 * layout order (NaN = dropout). */
	Output step(double time_s, double raw_dph, const double* temp_C);
	/** Batch form of step(), the same loop without a call per sample: for k = 0..n-1,
	 * out[k] = step(time_s[k], raw_dph[k], temp_C + k * temp_stride) (temperatures row by row,
	 * temp_stride >= layout size). Same state, same numbers, in any mix with step(). */
	void stepBatch(std::size_t n, const double* time_s, const double* raw_dph, const double* temp_C,
				   std::size_t temp_stride, Output* out);
	const CompensationCounters& counters() const { return counters_; }
	/** A turn-on of the gyro at time_s [s]: the warm-up term (if the calibration has one) runs
	 * from there. Without any call no warm-up term is added (the turn-on time is unknown). */
	void notePowerOn(double time_s);
	/** notePowerOn() at the turn-on the log's metadata `power_on_time_s` names, if it has one;
	 * throws std::invalid_argument when that value is not a time [s]. */
	void notePowerOnFromMetadata(const FogSeries& log);
	/** The applied axial magnetic field [uT] from the next step() on, held until the next call.
	 * A non-finite value means unknown (no field term; counted). Only a calibration with a
	 * magnetic section reads it; without any call the field is unknown. */
	void noteField(double field_uT);
	/** The calibration has a magnetic section: the field term needs noteField(). */
	bool readsField() const { return magnetic_.has_value(); }
	/** Forgets the state (rates, counters, the turn-on, the held scale factor, the field). */
	void reset();
	/** The build of the per-sample code in use: "avx2" or "portable". */
	const char* kernelBuild() const { return use_avx2_ ? "avx2" : "portable"; }

   private:
	/** One model compiled for the per-sample loop, and its signal groups: defined in
	 * internal/mrpt_fog/model/CompensatorStep.h (an implementation detail, not installed). */
	struct SignalGroup;
	struct EdgeSignal;
	struct Compiled;
	/** step() for NC == tracked channels (NC = 0: any count), kernel W lanes wide; defined in
	 * CompensatorStep.h, compiled once for baseline x86-64 (stepFixed, W = 2) and once for
	 * AVX2 (stepAvx2, CompensatorAvx2.cpp, NC = 1..4, W = 4), with bitwise the same results. */
	template <std::size_t NC, int W>
	Output stepBody(double time_s, double raw_dph, const double* temp_C);
	template <std::size_t NC>
	Output stepFixed(double time_s, double raw_dph, const double* temp_C);
	Output stepAvx2(double time_s, double raw_dph, const double* temp_C);  // 1..4 channels
	void stepBatchAvx2(std::size_t n, const double* time_s, const double* raw_dph, const double* temp_C,
					   std::size_t temp_stride, Output* out);
	template <std::size_t NC, int W>  // stepBatch's loop, CompensatorStep.h
	void stepLoop(std::size_t n, const double* time_s, const double* raw_dph, const double* temp_C,
				  std::size_t temp_stride, Output* out);
	static Compiled compile(const BiasModel& m, const std::vector<std::string>& channel_names,
							const std::vector<LagChannel>& lag_channels,
							const std::vector<HysteresisChannel>& hyst_channels);
	/** The lag bank's rates and the hysteresis bank's outputs for this sample (only when a model
	 * reads a lag or hysteresis signal): out of line. */
	void updateFilters(double time_s, const double* temp_C);
	template <std::size_t NB, int W>
	double evaluate(const Compiled& m, const double* temp_C, int& clamped) const;
	double addGroups(const Compiled& m, const double* temp_C, double sum, int& clamped) const;  // sum + the groups' terms
	/** Rare path after a clamp: the extrapolation policy's correction [deg/h] and the range counters. */
	double outsideRange(const Compiled& m, const double* temp_C);
	/** Delay-compensated rates (causal estimator of order 2): rate_ = 2 x slope over the last
	 * half window - slope over the whole window (exact for a quadratic signal). Out of line. */
	void delayCompensateRates(double time_s, const double* temp_C);
	/** Warm-up, magnetic term and scale factor (only when the calibration has one of them): out of line. */
	void applyExtras(Output& out, double time_s, double raw_dph, const double* temp_C);

	double window_s_;
	double half_window_s_;
	double mean_bias_dph_;
	ExtrapolationPolicy extrapolation_ = ExtrapolationPolicy::Linear;
	bool use_avx2_ = false;
	std::vector<int> channel_col_;  // layout column of each tracked channel
	bool same_order_ = false;  // channel_col_[c] == c for every tracked channel
	std::vector<Compiled> models_;  // [0] main, [1 + c] fallback without channel c (may be empty)
	std::vector<bool> has_fallback_;
	int startup_ = -1;  // index of the start-up model in models_, -1 none
	CausalRateTracker tracker_;
	bool delay_comp_ = false;  // causal estimator of order 2
	CausalRateTracker half_tracker_;  // the last half window (order 2 only)
	bool has_filters_ = false;  // some model reads a lag (dTlag/dt) or hysteresis (hyst) signal
	LagFilterBank lags_;  // over tracked channels
	std::vector<double> lag_rate_;  // per lag channel [degC/s]
	HysteresisFilterBank hyst_;  // over tracked channels
	std::vector<double> hyst_value_;  // per hysteresis channel, in [-1, 1]
	std::vector<double> temp_, rate_;  // per tracked channel, zero padded to the kernel's blocks of 4
	CompensationCounters counters_;
	static constexpr int kNoSampleYet = -2;  //!< last_model_ before the first sample
	int last_model_ = kNoSampleYet;
	bool extras_ = false;  // a scale-factor, warm-up or magnetic model is present
	std::optional<ScaleFactorModel> sf_;
	int sf_col_ = -1;  // layout column of the scale-factor thermistor
	std::vector<int> sf_cols_;  // or the columns whose mean it reads (ScaleFactorModel::thermistors)
	double sf_ppm_ = 0, sf_initial_ppm_ = 0;  // held value; value before any valid reading
	std::optional<WarmupModel> warmup_;
	double power_on_s_ = std::numeric_limits<double>::quiet_NaN();
	std::optional<MagneticModel> magnetic_;
	double field_uT_ = std::numeric_limits<double>::quiet_NaN();  // held applied field, NaN = unknown
};

/** Output of compensate(): columns of the same length as the input. */
struct CompensatedSeries
{
	std::vector<double> time_s;
	std::vector<double> raw_dph;  //!< primary-axis gyro rate [deg/h]
	std::vector<double> bias_dph;  //!< estimated thermal bias [deg/h]
	std::vector<double> compensated_dph;  //!< raw - bias [deg/h]
	std::vector<std::uint8_t> flags;  //!< CompensationFlag bits per sample
	CompensationCounters counters;
};

/** Compensates the calibrated axis of a series (validated first; throws std::invalid_argument
 * on a layout mismatch or a missing axis). Turn-ons for the warm-up term: the series' metadata
 * `power_on_time_s` (time_s of the turn-on that precedes or starts the log) and every 0 -> 1
 * step of its power column. The applied field for a magnetic section: the series' field_uT
 * column, sample by sample (NaN = unknown); a series without that column leaves the field
 * unknown (counters.field_unknown_samples; fieldMissingWarning() says so in words). */
CompensatedSeries compensate(const Calibration& cal, const FogSeries& series);

/** A one-line warning when `cal` has a magnetic section but `series` has no field column (the
 * field term cannot be applied: the output lacks it), else empty. For the programs that
 * compensate a log: never silently without the field. */
std::string fieldMissingWarning(const Calibration& cal, const FogSeries& series);

/** Receives the compensator's outputs for samples j0 .. j0 + m - 1 of `chunk` (run samples
 * k0 + j0 ..). */
using CompensationSink = std::function<void(const FogSeries& chunk, std::size_t k0, std::size_t j0, std::size_t m,
											const Compensator::Output* out)>;

/** compensate() over a run read chunk by chunk (obs/FogRun.h: memory independent of its length):
 * the same numbers, passed to `sink`; returns the counters. */
CompensationCounters compensateRun(const Calibration& cal, const FogRun& run, const CompensationSink& sink);

/** The bias column of compensate() alone (the same numbers; memory: one column, for the
 * programs that only need the estimated bias), with the counters through `counters`. */
std::vector<double> compensatedBias_dph(const Calibration& cal, const FogSeries& series,
										CompensationCounters* counters = nullptr);

/** The compensated-rate column of compensate() alone (the same numbers), with the counters. */
std::vector<double> compensatedRate_dph(const Calibration& cal, const FogSeries& series,
										CompensationCounters* counters = nullptr);

}  // namespace mrpt_fog
