/* mrpt_fog: long sweeps of the simulator (label "long"). */
#include <gtest/gtest.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/CoilThermalModel.h>

#include <cmath>
#include <iostream>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

TEST(DefaultDeviceSweep, SeedFiguresHoldAcrossNoiseSeeds)
{
	// The +-30 % match must not hinge on one noise realisation: 10 seeds at 10 Hz.
	const auto profile = ChamberProfile::preset("seed");
	double smin = 1e9, smax = 0, rmin = 1e9, rmax = 0;
	for (std::uint64_t seed = 1; seed <= 10; seed++)
	{
		SimSettings s;
		s.seed = seed;
		const FogSeries run = simulateChamber(profile, FogDevice::defaultDevice(), s);
		const BiasStats st = biasStats(run.time_s, run.rate_dph[2], 100.0);
		smin = std::min(smin, st.stability_dph);
		smax = std::max(smax, st.stability_dph);
		rmin = std::min(rmin, st.range_dph);
		rmax = std::max(rmax, st.range_dph);
		EXPECT_NEAR(st.stability_dph, 0.114857, 0.3 * 0.114857) << "seed " << seed;
		EXPECT_NEAR(st.range_dph, 0.5082, 0.3 * 0.5082) << "seed " << seed;
	}
	std::cout << "seeds 1..10: stability " << smin << " .. " << smax << " deg/h, range " << rmin << " .. " << rmax
			  << " deg/h\n";
}

TEST(DefaultDeviceSweep, EffectBreakdownOnSeedProfile)
{
	// Each effect alone (plus noise) on the seed profile: every thermal effect that the seed
	// profile can excite must change the 100 s figures relative to noise alone.
	const auto profile = ChamberProfile::preset("seed");
	auto figures = [&](const EffectSet& e) {
		SimSettings s;
		s.effects = e;
		const FogSeries run = simulateChamber(profile, FogDevice::defaultDevice(), s);
		return biasStats(run.time_s, run.rate_dph[2], 100.0);
	};
	const BiasStats none = figures({});
	std::cout << "noise only: stability " << none.stability_dph << " range " << none.range_dph << "\n";
	for (const auto& id : allEffectIds())
	{
		const BiasStats st = figures({id});
		std::cout << id << " alone: stability " << st.stability_dph << " range " << st.range_dph << "\n";
		// Effects the static seed profile does not excite: no table rate, no field, no power-on,
		// a constant Earth rate, and thermistor lag (affects temperatures, not the rate).
		if (id == "magnetic" || id == "warmup" || id == "earth_rate" || id == "thermistor_lag" || id == "heat_source" ||
			id == "scale_factor_temp")
			continue;
		EXPECT_GT(st.stability_dph, none.stability_dph * 1.05) << id;
	}
	const auto tau = CoilThermalModel(FogDevice::defaultDevice().thermal).timeConstants_s();
	std::cout << "thermal time constants [s]: slowest " << tau[tau.size() - 1] << ", " << tau[tau.size() - 2] << ", "
			  << tau[tau.size() - 3] << ", " << tau[tau.size() - 4] << "; fastest " << tau[0] << "\n";
}
