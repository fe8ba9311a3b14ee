/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// the same physics logged at another sample rate gives the same model. The default
// device on the seed profile at 1, 10 and 50 Hz (same device and seeds; the noise realisations
// differ with the rate). Measured (docs/validation/generalization.md): 10 and 50 Hz choose the same 9-term
// linear multipoint model, asserted here; 1 Hz adds T(To1)^2 and ^3 (printed, a documented miss);
// held-out stability on B 0.030 / 0.041 / 0.049 deg/h at 1 / 10 / 50 Hz (printed: whether the
// rise is the rate or the realisation is not settled by one seed, so it is not asserted).
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <cstdio>

using namespace mrpt_fog;

TEST(SampleRate, SamePhysicsSameModelAtTenAndFiftyHertz)
{
	const auto device = sim::FogDevice::defaultDevice();
	FitOptions o;
	o.stability_resamples = 0;
	std::vector<std::string> terms;
	std::vector<double> held_out;
	for (double hz : {1.0, 10.0, 50.0})
	{
		sim::SimSettings st;
		st.rate_hz = hz;
		st.seed = 7;
		const FogSeries A = sim::simulateChamber(sim::ChamberProfile::preset("seed"), device, st);
		st.seed = 8;
		const FogSeries B = sim::simulateChamber(sim::ChamberProfile::preset("B"), device, st);
		const Calibration cal = fitCalibration({A}, "multipoint", o);
		std::string t;
		for (const auto& n : cal.model.features.termNames()) t += n + " ";
		terms.push_back(t);
		held_out.push_back(evaluateCalibration(cal, B, "B").stability_dph);
		std::printf("  %5.1f Hz: %zu terms (%s), held-out stability on B %.4f deg/h\n", hz,
					cal.model.features.termCount(), t.c_str(), held_out.back());
	}
	EXPECT_EQ(terms[2], terms[1]);
}
