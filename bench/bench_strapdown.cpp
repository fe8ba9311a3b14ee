/* mrpt_fog: speed of the strapdown attitude update (one item = one gyro sample integrated).
 *  BM_Strapdown_ThreeAxis: updateRate with a 3-axis rate sample (trapezoid increments, coning
 *    correction, Earth-rate removal), 100 Hz.
 *  BM_Strapdown_VerticalOnly: updateRateZ, a single z-up FOG on a level vehicle (what fog-drift
 *    runs), 100 Hz.
 *  BM_Strapdown_Increment: updateIncrement with angle increments (integrating sensors). */
#include <benchmark/benchmark.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>

#include <cmath>

using namespace mrpt_fog::nav;

namespace
{
StrapdownOptions options()
{
	StrapdownOptions o;
	o.latitude_rad = 40.0 * M_PI / 180.0;
	o.sampling = RateSampling::Instantaneous;
	return o;
}
}  // namespace

static void BM_Strapdown_ThreeAxis(benchmark::State& state)
{
	StrapdownAttitude s(options(), StrapdownAttitude::Mode::ThreeAxis);
	s.initialize(0.0, Eigen::Quaterniond::Identity());
	double t = 0;
	Eigen::Vector3d w(1e-3, -2e-3, 0.05);
	for (auto _ : state)
	{
		t += 0.01;
		w.z() = 0.05 * std::sin(t);
		s.updateRate(t, w);
		benchmark::DoNotOptimize(s.attitude());
	}
	state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Strapdown_ThreeAxis);

static void BM_Strapdown_VerticalOnly(benchmark::State& state)
{
	StrapdownAttitude s(options(), StrapdownAttitude::Mode::VerticalOnly);
	s.initialize(0.0, Eigen::Quaterniond::Identity());
	double t = 0;
	for (auto _ : state)
	{
		t += 0.01;
		s.updateRateZ(t, 0.05 * std::sin(t));
		benchmark::DoNotOptimize(s.attitude());
	}
	state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Strapdown_VerticalOnly);

static void BM_Strapdown_Increment(benchmark::State& state)
{
	StrapdownAttitude s(options(), StrapdownAttitude::Mode::ThreeAxis);
	s.initialize(0.0, Eigen::Quaterniond::Identity());
	double t = 0;
	Eigen::Vector3d d(1e-5, -2e-5, 5e-4);
	for (auto _ : state)
	{
		t += 0.01;
		d.z() = 5e-4 * std::sin(t);
		s.updateIncrement(t, d);
		benchmark::DoNotOptimize(s.attitude());
	}
	state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Strapdown_Increment);

BENCHMARK_MAIN();
