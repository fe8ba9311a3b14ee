/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** Rows with the gyro off (power 0) have no gyro sample whatever their rate cell holds (
 * item 1): an empty cell (NaN) or a number (fog-sim's chamber writes 0 deg/h there). The raw
 * figures of a calibration (in-sample) and of its validation must be those of the powered
 * samples alone, computed here with metrics::biasStats on the powered rows (not by the
 * calibration code). Formerly a 0 in the cell entered fog-calibrate's raw stability
 * (0.41 -> 2.68 deg/h on fog-sim's `rich` chamber profile). */
#include <gtest/gtest.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/Calibration.h>

#include <cmath>
#include <limits>
#include <vector>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

TEST(PowerOffRows, RawFiguresAreThoseOfThePoweredSamplesWhateverTheOffCellsHold)
{
	FogSeries zero = fogtest::makeCoilRun("B", 11);
	zero.power.assign(zero.size(), 1.0);
	std::vector<double> t_on, r_on;  // the truth: the powered samples
	for (std::size_t k = 0; k < zero.size(); k++)
	{
		const double t = zero.time_s[k];
		if (t >= 9000 && t < 12000)
		{
			zero.power[k] = 0.0;
			zero.rate_dph[2][k] = 0.0;  // a number that is no measurement
		}
		else
			t_on.push_back(t), r_on.push_back(zero.rate_dph[2][k]);
	}
	FogSeries empty = zero;
	for (std::size_t k = 0; k < empty.size(); k++)
		if (empty.power[k] == 0.0) empty.rate_dph[2][k] = std::numeric_limits<double>::quiet_NaN();
	const BiasStats expected = biasStats(t_on, r_on, 100.0);
	ASSERT_GT(expected.stability_dph, 0.0);

	for (const FogSeries* s : {&empty, &zero})
	{
		SCOPED_TRACE(s == &zero ? "power 0 rows holding 0 deg/h" : "power 0 rows with an empty rate");
		const Calibration cal = fitCalibration({*s}, "multipoint");
		EXPECT_NEAR(cal.in_sample.raw_stability_dph, expected.stability_dph, 1e-12 * expected.stability_dph);
		EXPECT_NEAR(cal.in_sample.raw_range_dph, expected.range_dph, 1e-12 * expected.range_dph);
		const FitFigures v = evaluateCalibration(cal, *s, "validation");
		EXPECT_NEAR(v.raw_stability_dph, expected.stability_dph, 1e-12 * expected.stability_dph);
		EXPECT_NEAR(v.raw_range_dph, expected.range_dph, 1e-12 * expected.range_dph);
	}
}
