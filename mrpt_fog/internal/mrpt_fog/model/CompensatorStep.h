/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CompensatorStep.h
 * The body of Compensator::step (implementation detail: included only by Compensator.cpp and
 * CompensatorAvx2.cpp, which compile it for baseline x86-64 and for AVX2 respectively).
 * Everything it calls on the hot path is inline, so each build gets its own instructions;
 * the rare paths (the tracker's general update, the difference groups) are ordinary calls.
 */

#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/CausalRateTrackerInline.h>
#include <mrpt_fog/model/CompensatorKernel.h>

#include <cmath>
#include <cstring>

namespace mrpt_fog
{
/** The signals of one kind (T, dT/dt, dT, d/dt dT) of a model, struct-of-arrays, every
 * polynomial padded with zeros to the group's highest degree: clamping, normalisation and
 * Horner then run as fixed-length, branch-free loops over the signals. */
struct Compensator::SignalGroup
{
	SignalKind kind = SignalKind::Temp;
	int degree = 0;
	std::vector<int> a, b;  // tracked-channel indices
	std::vector<double> centre, inv_scale, lo, hi;
	std::vector<double> p;  // coefficient of z^k of signal i at p[k * n + i], k = 1..degree
};

/** A compiled model. Per-channel kernel for the T(c) and dT/dt(c) terms (the multipoint shape),
 * in blocks of 4 tracked channels (the last block padded), normalisation folded into the
 * coefficients (CompensatorKernel.h); the other terms as signal groups. */
/** One signal's calibrated range and the bias slope at its edges (extrapolation, the rare path). */
struct Compensator::EdgeSignal
{
	int kind = 0, a = 0, b = 0;  // SignalKind, tracked channels (LagRate: a = lag channel, Hysteresis: its operator)
	double lo = 0, hi = 0, slope_lo = 0, slope_hi = 0;  // [signal unit], [deg/h per unit]
	double centre = 0, scale = 1, coef[6] = {0, 0, 0, 0, 0, 0};  // coef[k] of z^k (Polynomial policy)
};

struct Compensator::Compiled
{
	double c0 = 0;
	std::vector<EdgeSignal> edges;
	std::vector<detail::KernelBlock> kernel;
	std::vector<SignalGroup> groups;  // differences and their rates
	std::uint32_t uses = 0;  // bit mask of the channels the model reads (temperature or rate)
	std::uint32_t uses_rate = 0;  // the channels whose rate (or a difference's rate) it reads
};

template <std::size_t NB, int W>
[[gnu::always_inline]] inline double Compensator::evaluate(const Compiled& m, const double* temp_C, int& clamped) const
{
	// The per-channel kernel inline; the difference groups (other presets) out of line.
	double sum = m.c0;
	sum += detail::kernelSum<NB, W>(m.kernel.data(), m.kernel.size(), temp_C, rate_.data(), clamped);
	if (!m.groups.empty()) sum = addGroups(m, temp_C, sum, clamped);
	return sum;
}

template <std::size_t NC, int W>
[[gnu::always_inline]] inline Compensator::Output Compensator::stepBody(double time_s, double raw_dph,
																		 const double* temp_C)
{
	const std::size_t nc = NC ? NC : channel_col_.size();
	constexpr std::size_t NB = NC ? (NC + 3) / 4 : 0;  // kernel blocks
	// The temperatures the tracker and the kernel read. Same column order and a whole block (the
	// usual 4-thermistor case): the caller's row itself, no copy. Otherwise the work buffer
	// (zero padded to whole blocks), filled as a block copy when the order is the same
	// (element-wise stores read back as vectors would stall store forwarding).
	const double* T = temp_C;
	if (!(NC == 4 && same_order_))
	{
		if (same_order_ && nc > 0)  // nc == 0 (constant-only model): memcpy with a null buffer is UB
			std::memcpy(temp_.data(), temp_C, nc * sizeof(double));  // own buffer: no overlap
		else
			for (std::size_t c = 0; c < nc; c++) temp_[c] = temp_C[channel_col_[c]];
		T = temp_.data();
	}
	tracker_.pushFixed<NC>(time_s, same_order_ ? temp_C : temp_.data());
	if (__builtin_expect(has_filters_, 0)) updateFilters(time_s, same_order_ ? temp_C : temp_.data());
	const std::uint32_t short_span = tracker_.ratesAndCoverageFixed<NC>(rate_.data(), half_window_s_);
	if (__builtin_expect(delay_comp_, 0)) delayCompensateRates(time_s, same_order_ ? temp_C : temp_.data());
	// One predictable test for the common case: is any reading or rate NaN? (Then the mask of
	// missing channels is built element by element; an infinite value is not missing.)
	bool any_nan;
	if constexpr (NC == 4)
		any_nan = detail::vec::anyNaNSum<W>(T, rate_.data()) || (W == 2 && detail::vec::anyNaNSum<W>(T + 2, rate_.data() + 2));
	else
	{
		double all = 0.0;
		for (std::size_t c = 0; c < nc; c++) all += T[c] + rate_[c];
		any_nan = std::isnan(all);
	}
	std::uint32_t missing_t = 0, missing_r = 0;  // channels without a reading / without a rate
	if (any_nan)  // dropout or no rate yet (rare): zero what is missing, never read by the model in use
	{
		if (T != temp_.data())
		{
			std::memcpy(temp_.data(), temp_C, nc * sizeof(double));
			T = temp_.data();
		}
		for (std::size_t c = 0; c < nc; c++)
		{
			if (std::isnan(temp_[c]))
			{
				missing_t |= 1u << c;
				temp_[c] = 0.0;
			}
			if (std::isnan(rate_[c]))
			{
				missing_r |= 1u << c;
				rate_[c] = 0.0;
			}
		}
	}
	const auto lacks = [&](const Compiled& m) { return (missing_t & m.uses) | (missing_r & m.uses_rate); };
	// With a start-up model, a rate window covering less than half its length counts as lacking
	// too (a rate from a few samples); without one the model is used with it (flag RateWarmup).
	const std::uint32_t warming = startup_ >= 0 ? short_span : 0;
	// Main model unless it lacks a reading or a rate (or, with a start-up model, waits for one);
	// else, when every reading it needs is there (only rates lack), the rate-free start-up model;
	// else the fallback without the first channel it lacks, if that fallback lacks nothing (its
	// rates may still be warming up: flagged); else the main model with warming rates; else none.
	int model = -1;
	const std::uint32_t lack_main = lacks(models_[0]), warm_main = warming & models_[0].uses_rate;
	if ((lack_main | warm_main) == 0)
		model = 0;
	else if (startup_ >= 0 && (missing_t & models_[0].uses) == 0 && lacks(models_[startup_]) == 0)
		model = startup_;
	else
	{
		const int c = __builtin_ctz(lack_main ? lack_main : warm_main);
		if (has_fallback_[c] && lacks(models_[1 + c]) == 0)
			model = 1 + c;
		else if (lack_main == 0)
			model = 0;
	}
	Output out;
	int clamped = 0;
	bool warm = false;
	if (model >= 0)
	{
		out.bias_dph = evaluate<NB, W>(models_[model], T, clamped);
		warm = (short_span & models_[model].uses_rate) != 0;
	}
	else
		out.bias_dph = mean_bias_dph_;
	const bool rate_free = model == startup_ && startup_ >= 0;
	out.compensated_dph = raw_dph - out.bias_dph;
	out.model = rate_free ? kStartupModel : model;
	counters_.samples++;
	if (model != last_model_)
	{
		counters_.model_switches += last_model_ != kNoSampleYet;
		last_model_ = model;
	}
	if (model == 0 && clamped == 0 && !warm)  // the common case: no flag, no other counter
	{
		// warm-up term and scale factor, only when the calibration has one (out of line)
		if (__builtin_expect(extras_, 0)) applyExtras(out, time_s, raw_dph, temp_C);
		return out;
	}
	if (clamped)
	{
		out.bias_dph += outsideRange(models_[model], T);
		out.compensated_dph = raw_dph - out.bias_dph;
	}
	if (model > 0 && !rate_free) out.flags |= CompensationFlag::Fallback;
	if (rate_free) out.flags |= CompensationFlag::RateFree;
	if (model < 0) out.flags |= CompensationFlag::NoModel;
	if (clamped) out.flags |= CompensationFlag::Clamped;
	if (warm) out.flags |= CompensationFlag::RateWarmup;
	counters_.fallback_samples += model > 0 && !rate_free;
	counters_.rate_free_samples += rate_free;
	counters_.no_model_samples += model < 0;
	counters_.clamped_samples += clamped > 0;
	counters_.clamped_signals += static_cast<std::size_t>(clamped);
	counters_.warmup_samples += warm;
	if (extras_) applyExtras(out, time_s, raw_dph, temp_C);
	return out;
}

template <std::size_t NC, int W>
[[gnu::always_inline]] inline void Compensator::stepLoop(std::size_t n, const double* time_s, const double* raw_dph,
														 const double* temp_C, std::size_t temp_stride, Output* out)
{
	for (std::size_t k = 0; k < n; k++)
	{
		// field by field: a whole-struct copy of the just-built Output would read back its
		// element-wise stores as one wide load (a store-forwarding stall on every sample)
		const Output o = stepBody<NC, W>(time_s[k], raw_dph[k], temp_C + k * temp_stride);
		out[k].bias_dph = o.bias_dph;
		out[k].compensated_dph = o.compensated_dph;
		out[k].flags = o.flags;
		out[k].model = o.model;
	}
}

}  // namespace mrpt_fog
