/* StandstillCorrection: the field refiner behind the pipeline's per-sample RateCorrection. */
#include <gtest/gtest.h>
#include <mrpt_fog_heading/StandstillCorrection.h>

#include <cmath>
#include <random>

using namespace mrpt_fog::heading;

namespace
{
/** 10 Hz: still for stop_s, then driving straight at 5 m/s; the compensated gyro reads the
 * still reading + offset + white noise (ARW 0.001 deg/sqrt h). Returns the last corrected rate
 * minus the last compensated one. */
double run(double offset_dph, double stop_s, double total_s, StandstillCorrection& c)
{
	std::mt19937_64 rng(4);
	std::normal_distribution<double> w(0.0, 0.06 / std::sqrt(0.1));
	double x = 0, out = 0;
	for (int k = 0; k * 0.1 <= total_s + 1e-9; k++)
	{
		const double t = 1000.0 + k * 0.1;
		if (k * 0.1 > stop_s) x += 0.5;
		WheelOdometry o;
		o.t_s = t, o.x_m = x;
		c.noteOdometry(o);
		RateCorrectionInput in;
		in.t_s = t;
		in.still_reading_dph = 9.668;
		in.compensation_sigma_dph = 0.01;
		in.compensated_dph = 9.668 + offset_dph + w(rng);
		out = c.correct(in) - in.compensated_dph;
	}
	c.finish();
	return out;
}
}  // namespace

// A 120 s stop learns the offset, which is then subtracted (causal, per sample).
TEST(StandstillCorrection, StopLearnsTheOffset)
{
	StandstillCorrection c;
	const double d = run(0.3, 120, 300, c);
	ASSERT_NE(c.refiner(), nullptr);
	ASSERT_EQ(c.refiner()->updates().size(), 1u);
	EXPECT_TRUE(c.refiner()->applied());
	EXPECT_NEAR(-d, 0.3, 4 * c.refiner()->filter().offset_sigma_dph() + 0.01);
}

// No standstill: the pipeline's rate passes unchanged.
TEST(StandstillCorrection, NoStandstillChangesNothing)
{
	StandstillCorrection c;
	EXPECT_EQ(run(0.3, 0, 300, c), 0.0);
	EXPECT_TRUE(c.refiner()->updates().empty());
}

// The prior's thermal share: what a bias offset is uncertain by, not the per-sample residual.
TEST(StandstillCorrection, ThermalModelSigmaIsTheHeldOutStability)
{
	mrpt_fog::Calibration cal;
	cal.model.rms_held_out_dph = 0.19;  // per-sample residual: not a bias uncertainty
	cal.held_out.stability_dph = 0.013;
	cal.in_sample.stability_dph = 0.011;
	EXPECT_EQ(thermalModelSigma_dph(cal), 0.013);
	cal.held_out.stability_dph = NAN;
	EXPECT_EQ(thermalModelSigma_dph(cal), 0.011);
	cal.in_sample.stability_dph = 0.0;
	EXPECT_EQ(thermalModelSigma_dph(cal), 0.0);
}
