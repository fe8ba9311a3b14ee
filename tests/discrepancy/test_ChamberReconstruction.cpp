/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/SimulatedRun.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <cmath>
#include <cstdio>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
/** A fog-sim run of a preset at 0.05 Hz, its metadata cleared (no profile known), and the
 * configuration of the same device (the network is right: only the air is unknown). */
struct Case
{
	FogSeries run;
	sim::ChamberProfile profile;
	SimulatorConfig cfg;
};
Case makeCase(const std::string& preset, std::uint64_t seed)
{
	Case c;
	c.profile = sim::ChamberProfile::preset(preset);
	sim::SimSettings st;
	st.rate_hz = 0.05;
	st.seed = seed;
	st.profile_source = preset;
	st.effects = {"shupe_rate", "radial_gradient", "heat_source", "earth_rate", "thermistor_lag"};
	c.run = sim::simulateChamber(c.profile, sim::FogDevice::defaultDevice(), st);
	c.run.metadata.clear();
	c.cfg.source = "test";
	c.cfg.effects = st.effects;
	return c;
}
}  // namespace

// Truth: the preset's programmed air. On the seed profile (holds and 1 C/min ramps: piecewise
// linear, what the reconstruction can represent), the reconstructed air must follow the program
// and the stated 95 % intervals must cover it at most knots. Knots whose air has not yet reached
// the thermistors (the last 30 min) are not judged: their interval is wide by design.
TEST(ChamberReconstruction, SeedProfileAirIsRecoveredWithinItsInterval)
{
	const Case c = makeCase("seed", 11);
	const ChamberDrive d = chamberDriveForRun(c.run, c.cfg);
	ASSERT_EQ(d.source, DriveSource::MeasuredLog);
	const auto& a = d.air;
	std::size_t judged = 0, covered = 0;
	double ss = 0, maxErr = 0;
	for (std::size_t m = 0; m < a.knot_time_s.size(); ++m)
	{
		if (a.knot_time_s[m] > a.knot_time_s.back() - 1800) break;
		const double err = a.knot_air_C[m] - c.profile.stateAt(a.knot_time_s[m]).air_C;
		judged++;
		covered += std::abs(err) <= a.knot_ci95_half_C[m];
		ss += err * err;
		maxErr = std::max(maxErr, std::abs(err));
	}
	const double rms = std::sqrt(ss / static_cast<double>(judged));
	std::printf("  seed profile: %zu knots judged, air error RMS %.3g C, max %.3g C, covered %zu/%zu, thermistor fit %.3g C, "
				"mean half-width %.3g C\n",
				judged, rms, maxErr, covered, judged, a.fit_rms_C, a.mean_ci95_half_C);
	EXPECT_LT(rms, 0.5);
	EXPECT_GE(static_cast<double>(covered), 0.9 * static_cast<double>(judged));
	EXPECT_LT(a.fit_rms_C, 0.02);  // thermistor noise 0.003 C + quantum 0.01 C
	// The drive reproduces the run's power column.
	for (std::size_t k = 0; k < c.run.size(); ++k)
		ASSERT_EQ(d.stateAt(d.sim_index[k]).power_on, c.run.gyroOn(k)) << k;
}

TEST(ChamberReconstruction, RunWithoutReadingsIsAClearError)
{
	Case c = makeCase("seed", 12);
	for (auto& col : c.run.temp_C)
		for (double& v : col) v = NAN;
	EXPECT_THROW(chamberDriveForRun(c.run, c.cfg), std::invalid_argument);
}
