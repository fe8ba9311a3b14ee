/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// FitOptions::turn_on_exclusion_s on one synthetic run that starts with a turn-on and then ramps
// the temperature (made here from a closed form, not by the code under test): bias
// b0 + b1 (T - 25) + A exp(-(t - t_on) / tau). In the bias fit the warm-up, which sits at the
// cold end of the ramp, is taken for a temperature slope (least squares: about -2.8e-3 deg/h/C
// for the numbers below, against the true 4e-3); with the first hour left out the slope comes
// back, and fitWarmup on the same run finds A and tau.
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationRecipe.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/WarmupFit.h>

#include <cmath>
#include <limits>
#include <random>

using namespace mrpt_fog;

namespace
{
constexpr double kB0_dph = 0.3, kB1_dph_per_C = 0.004, kWarmA_dph = 1.0, kWarmTau_s = 600.0;

/** off_s unpowered at -20 C, then on: the temperature ramps -20 -> 40 C over ramp_s (1 Hz). With
 * metadata_turn_on, no power column and metadata power_on_time_s at the first sample instead. */
FogSeries coldStartRamp(unsigned seed, double off_s, double ramp_s, bool metadata_turn_on)
{
	std::mt19937_64 rng(seed);
	std::normal_distribution<double> n01;
	FogSeries s;
	s.sensor_label = "FOG";
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}};
	s.temp_C.resize(1);
	const double t_on = off_s;
	for (int k = 0; k < static_cast<int>(off_s + ramp_s); k++)
	{
		const double t = k;
		const bool on = t >= t_on;
		const double T = on ? -20.0 + 60.0 * (t - t_on) / ramp_s : -20.0;
		const double bias = kB0_dph + kB1_dph_per_C * (T - 25.0) + kWarmA_dph * std::exp(-(t - t_on) / kWarmTau_s);
		s.time_s.push_back(t);
		s.rate_dph[2].push_back(on ? bias + 0.01 * n01(rng) : std::nan(""));
		s.temp_C[0].push_back(T + 0.002 * n01(rng));
		if (!metadata_turn_on) s.power.push_back(on ? 1.0 : 0.0);
	}
	if (metadata_turn_on) s.setMetadata("power_on_time_s", "0");
	return s;
}

/** The calibration's bias slope [deg/h/C], from its bias at 0 and 30 C (a powered run, no turn-on). */
double slopeOf(const Calibration& cal)
{
	FogSeries s;
	s.sensor_label = "FOG";
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}};
	s.temp_C.resize(1);
	for (int k = 0; k < 2; k++)
	{
		s.time_s.push_back(k);
		s.rate_dph[2].push_back(0.0);
		s.temp_C[0].push_back(k == 0 ? 0.0 : 30.0);
	}
	const std::vector<double> b = compensatedBias_dph(cal, s);
	return (b[1] - b[0]) / 30.0;
}
}  // namespace

TEST(TurnOnExclusion, WarmupStaysOutOfTheBiasFitAndIsFittedOnTheSameRun)
{
	const FogSeries run = coldStartRamp(3, 300, 20000, false);
	FitOptions opt;
	opt.selection = TermSelection::None;
	const Calibration in_fit = fitCalibration({run}, "M1:Ti1@1/0", opt);
	// the warm-up in the bias fit: the slope is pulled far from the truth (closed form: ~ -2.8e-3)
	EXPECT_LT(slopeOf(in_fit), 0.5 * kB1_dph_per_C);

	opt.turn_on_exclusion_s = kSuggestedTurnOnExclusion_s;  // 6 tau
	const Calibration out = fitCalibration({run}, "M1:Ti1@1/0", opt);
	// left: exp(-6) of the warm-up over the first hours of the fit, < 1e-5 deg/h/C of slope
	EXPECT_NEAR(slopeOf(out), kB1_dph_per_C, 5e-5);
	EXPECT_LT(out.model.samples, in_fit.model.samples);
	EXPECT_NEAR(static_cast<double>(in_fit.model.samples - out.model.samples), kSuggestedTurnOnExclusion_s, 1.0);

	const WarmupModel w = fitWarmup({run}, out);
	EXPECT_NEAR(w.amplitude_dph, kWarmA_dph, std::max(3 * w.amplitude_std_dph, 0.05));
	EXPECT_NEAR(w.tau_s, kWarmTau_s, std::max(3 * w.tau_std_s, 60.0));
}

TEST(TurnOnExclusion, MetadataTurnOnAtTheFirstSampleAndBadValues)
{
	const FogSeries run = coldStartRamp(4, 0, 20000, true);
	FitOptions opt;
	opt.selection = TermSelection::None;
	opt.turn_on_exclusion_s = kSuggestedTurnOnExclusion_s;
	const Calibration out = fitCalibration({run}, "M1:Ti1@1/0", opt);
	EXPECT_NEAR(slopeOf(out), kB1_dph_per_C, 5e-5);
	// a run without a turn-on loses nothing to the exclusion (the first sample has no rate yet)
	FogSeries powered = run;
	powered.setMetadata("power_on_time_s", "");
	const Calibration all = fitCalibration({powered}, "M1:Ti1@1/0", opt);
	EXPECT_GE(all.model.samples, 19999u);
	EXPECT_NEAR(static_cast<double>(all.model.samples - out.model.samples), kSuggestedTurnOnExclusion_s, 1.0);

	for (double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()})
	{
		opt.turn_on_exclusion_s = bad;
		EXPECT_THROW(fitCalibration({run}, "M1:Ti1@1/0", opt), std::invalid_argument) << bad;
	}
}

// The recipe (CalibrationRecipe.h) with nothing but the run: the hour after the turn-on stays out
// of the bias fit by default and the same run fits the warm-up term (the closed form's slope, A
// and tau come back); a copy of the run that is never powered holds no turn-on although its
// metadata names one.
TEST(TurnOnExclusion, TheRecipeDefaultFitsTheWarmupOnTheRunWithTheTurnOn)
{
	const FogSeries run = coldStartRamp(5, 300, 20000, false);
	CalibrationRuns in;
	in.runs.emplace_back(run);
	in.labels.push_back("cold start");
	CalibrateOptions opt;
	opt.model = "M1:Ti1@1/0";
	opt.fit.selection = TermSelection::None;
	const CalibrationOutcome out = calibrate(in, opt);
	ASSERT_EQ(out.axes.size(), 1u);
	ASSERT_EQ(out.turn_ons.size(), 1u);
	EXPECT_EQ(out.turn_ons[0].turn_on_events, 1u);
	EXPECT_EQ(out.turn_ons[0].use, TurnOnUse::Use::ExcludedToWarmupFit);
	const Calibration& cal = out.axes[0].cal;
	EXPECT_NEAR(slopeOf(cal), kB1_dph_per_C, 5e-5);
	ASSERT_TRUE(cal.warmup.has_value());
	EXPECT_NEAR(cal.warmup->amplitude_dph, kWarmA_dph, std::max(3 * cal.warmup->amplitude_std_dph, 0.05));
	EXPECT_NEAR(cal.warmup->tau_s, kWarmTau_s, std::max(3 * cal.warmup->tau_std_s, 60.0));

	FogSeries off = run;
	for (auto& p : off.power) p = 0.0;
	off.setMetadata("power_on_time_s", "0");
	EXPECT_EQ(turnOnsOf(FogRun(off), "off").turn_on_events, 0u);
	EXPECT_FALSE(turnOnsOf(FogRun(off), "off").power_on_metadata);
	EXPECT_TRUE(turnOnsOf(FogRun(run), "on").turn_on_events == 1u);
}
