/* mrpt_fog: speed of the FOG simulator (one item = one output gyro sample).
 *  BM_SimulateChamber_Seed10Hz: the whole seed chamber run (405 min, 10 Hz, 243001 samples) of
 *    the default device with every error effect: the command fog-sim runs for the seed dataset.
 *  BM_FogSimulator_Advance/dt_ms: FogSimulator::advance alone (coil thermal network, Shupe
 *    integral, error effects, thermistors, noise) on a 1 degC/min ramp, at 10 Hz and 100 Hz. */
#include <benchmark/benchmark.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

static void BM_SimulateChamber_Seed10Hz(benchmark::State& state)
{
	const ChamberProfile profile = ChamberProfile::preset("seed");
	const FogDevice device = FogDevice::defaultDevice();
	SimSettings s;
	s.rate_hz = 10.0;
	std::size_t samples = 0;
	for (auto _ : state)
	{
		const FogSeries run = simulateChamber(profile, device, s);
		samples += run.size();
		benchmark::DoNotOptimize(run.rate_dph[2].data());
	}
	state.SetItemsProcessed(static_cast<int64_t>(samples));
	state.counters["samples_per_run"] = static_cast<double>(samples) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_SimulateChamber_Seed10Hz)->Unit(benchmark::kMillisecond)->Iterations(3);

static void BM_FogSimulator_Advance(benchmark::State& state)
{
	const double dt_s = static_cast<double>(state.range(0)) * 1e-3;
	FogSimulator sim(FogDevice::defaultDevice(), defaultEffects(), 1);
	ChamberState c;
	c.air_C = 25.0;
	sim.start(c, InitialThermalState::Steady);
	double t = 0;
	for (auto _ : state)
	{
		t += dt_s;
		c.air_C = 25.0 + std::fmod(t / 60.0, 40.0);  // 1 degC/min saw tooth between 25 and 65 degC
		const FogSample smp = sim.advance(dt_s, c);
		benchmark::DoNotOptimize(smp.rate_dph);
	}
	state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FogSimulator_Advance)->Arg(100)->Arg(10);

BENCHMARK_MAIN();
