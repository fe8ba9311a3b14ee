/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// Lab data as it comes, on the independent sector-coil generator (never
// used to tune anything): the same device logged at 0.1 Hz .. 100 Hz, and its thermistors
// quantised to 0.01, 1/256, 1/16 and 1 degC. Each run is calibrated on the seed profile and
// evaluated on profile B; the figure is the held-out 100 s stability over the device's noise
// floor on B (the same run without thermal error). Long label: the 100 Hz run is 3.4 M samples.
#include "SectorCoilGenerator.h"

#include <gtest/gtest.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/Calibration.h>

#include <cstdio>
#include <string>

using namespace fogtest;
using namespace mrpt_fog;

namespace
{
struct Outcome
{
	std::string terms;
	double window_s = 0, ratio = 0;
};

Outcome calibrateAndEvaluate(const SectorCoilParams& p, const FitOptions& o)
{
	const auto seed = sim::ChamberProfile::preset("seed"), B = sim::ChamberProfile::preset("B");
	const Calibration cal = fitCalibration({simulateSectorCoil(p, seed, 21)}, "multipoint", o);
	const FogSeries eval = simulateSectorCoil(p, B, 22), floor = simulateSectorCoil(p, B, 22, true);
	Outcome out;
	for (const auto& n : cal.model.features.termNames()) out.terms += n + " ";
	out.window_s = cal.rate_estimator.window_s;
	out.ratio = evaluateCalibration(cal, eval, "B").stability_dph /
				biasStats(floor.time_s, floor.primaryRate_dph(), 100.0).stability_dph;
	return out;
}
}  // namespace

// Sample rate: the rate window is a time (60 s), not a sample count; the same physics should
// give the same model and the same held-out figure at every rate. Measured (device 1): held-out /
// floor 1.003 / 1.021 / 1.049 / 1.058 at 0.1 / 1 / 10 / 100 Hz, the same terms at 10 and 100 Hz,
// T^2 (0.1 Hz) and T^2, T^3 (1 Hz) added at the low rates: the same figure, not the same
// terms. Asserted: what the requirement says (the same terms at 1, 10 and 100 Hz; every held-out
// ratio within 25 % of the 10 Hz one), so this test FAILS today on the 1 Hz terms: a known miss
// (docs/validation/generalization.md), kept red rather than relaxed to what held.
TEST(LabData, SectorCoilSampleRatesGiveTheSameModel)
{
	SectorCoilParams p = drawSectorCoil(1);
	p.quantum_C = 0.01;
	FitOptions o;
	o.stability_resamples = 0;
	std::vector<Outcome> r;
	const double rates[] = {0.1, 1.0, 10.0, 100.0};
	for (const double hz : rates)
	{
		p.rate_hz = hz;
		r.push_back(calibrateAndEvaluate(p, o));
		std::printf("  %6.1f Hz: window %g s, held-out / floor on B %.3f, terms %s\n", hz, r.back().window_s,
					r.back().ratio, r.back().terms.c_str());
	}
	EXPECT_EQ(r[1].terms, r[2].terms);
	EXPECT_EQ(r[3].terms, r[2].terms);
	for (std::size_t i = 1; i < r.size(); i++) EXPECT_NEAR(r[i].ratio, r[2].ratio, 0.25 * r[2].ratio) << rates[i];
}

// Quantisation: the default lengthens the rate window with the readings' quantum
// (windowForQuantum_s); compared with the fixed 60 s window (fog-calibrate --window 60) and with
// the rate-free model (multipoint@3/0, selection none). Measured (device 1, 1 Hz, at 0c62892):
// 0.01 C 1.474 and 1/256 C 1.196 (window 60 s both ways); 1/16 C default (188 s) 1.131 vs fixed
// 60 s 1.237; 1 C default (1200 s) 1.919 vs fixed 2.150 vs rate-free 9.09. Asserted: with 1/16
// and 1 degC quanta the default is no worse than the fixed window (2 %). With the earlier 375 s
// window at 1/16 C this failed (4 % worse than 60 s); the 188 s rule was chosen on the
// generalization bench's tuning seeds, not on this device.
TEST(LabData, SectorCoilQuantisedThermistors)
{
	SectorCoilParams p = drawSectorCoil(1);
	p.rate_hz = 1.0;
	for (const double q : {0.01, 1.0 / 256, 1.0 / 16, 1.0})
	{
		p.quantum_C = q;
		FitOptions def, fixed, rate_free;
		def.stability_resamples = fixed.stability_resamples = 0;
		fixed.window_for_quantum = false;
		const Outcome a = calibrateAndEvaluate(p, def), b = calibrateAndEvaluate(p, fixed);
		rate_free.selection = TermSelection::None;
		const auto seed = sim::ChamberProfile::preset("seed"), B = sim::ChamberProfile::preset("B");
		const Calibration cal_rf = fitCalibration({simulateSectorCoil(p, seed, 21)}, "multipoint@3/0", rate_free);
		const FogSeries eval = simulateSectorCoil(p, B, 22), floor = simulateSectorCoil(p, B, 22, true);
		const double rf = evaluateCalibration(cal_rf, eval, "B").stability_dph /
						  biasStats(floor.time_s, floor.primaryRate_dph(), 100.0).stability_dph;
		std::printf("  quantum %.4g C: default (window %g s) %.3f, fixed 60 s %.3f, rate-free @3/0 %.3f\n", q, a.window_s,
					a.ratio, b.ratio, rf);
		if (q >= 1.0 / 16) EXPECT_LE(a.ratio, b.ratio * 1.02) << q;
	}
}
