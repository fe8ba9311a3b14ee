/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* Speed of the thermal-bias model (one item = one gyro sample):
 *  BM_Compensate_Multipoint4: Compensator::step with the 4-thermistor 5/3 multipoint model (33
 *    terms, plain fit so that every term is present), causal rates of the 4 thermistors included;
 *    the label says which build ran (avx2 / portable). _Portable: the baseline build forced.
 *    _Batch: Compensator::stepBatch over the run (same numbers, no call per sample).
 *  BM_Fit_Multipoint4/N: the streaming fit core on N samples: causal rates + 33 normalised
 *    features + streaming QR accumulation (StreamingQr) + the final solve. Data cycles over one synthetic
 *    chamber run (time shifted each cycle), so memory holds one run whatever N is; the counter
 *    peak_rss_MB (process high-water mark after the run) shows it does not grow with N. */
#include <benchmark/benchmark.h>
#include <mrpt_fog/model/BiasFit.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/ModelPreset.h>
#include <sys/resource.h>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
const FogSeries& run()
{
	static const FogSeries s = fogtest::makeCoilRun("A", 7);
	return s;
}
const Calibration& cal()
{
	static const Calibration c = [] {
		FitOptions o;
		o.selection = TermSelection::None;
		o.fallbacks = true;
		return fitCalibration({run()}, "multipoint", o);
	}();
	return c;
}
/** Samples in row-major order (temperatures interleaved) for cache-friendly streaming. */
struct Rows
{
	std::vector<double> t, rate, temp;  // temp[k * 4 + i]
};
const Rows& rows()
{
	static const Rows r = [] {
		Rows r;
		const auto& s = run();
		for (std::size_t k = 0; k < s.size(); k++)
		{
			r.t.push_back(s.time_s[k]);
			r.rate.push_back(s.rate_dph[2][k]);
			for (int i = 0; i < 4; i++) r.temp.push_back(s.temp_C[i][k]);
		}
		return r;
	}();
	return r;
}
double peakRssMB()
{
	rusage u{};
	getrusage(RUSAGE_SELF, &u);
	return static_cast<double>(u.ru_maxrss) / 1024.0;
}
}  // namespace

static void compensateMultipoint4(benchmark::State& state, KernelBuild build, bool batch)
{
	const auto& r = rows();
	const std::size_t n = r.t.size();
	const double period = r.t.back() + 1.0;
	Compensator comp(cal(), run().thermistors, build);
	std::vector<double> t(n);
	std::vector<Compensator::Output> out(n);
	double sink = 0, offset = 0;
	for (auto _ : state)
	{
		if (batch)
		{
			for (std::size_t k = 0; k < n; k++) t[k] = r.t[k] + offset;
			comp.stepBatch(n, t.data(), r.rate.data(), r.temp.data(), 4, out.data());
			for (std::size_t k = 0; k < n; k++) sink += out[k].compensated_dph;
		}
		else
			for (std::size_t k = 0; k < n; k++) sink += comp.step(r.t[k] + offset, r.rate[k], &r.temp[4 * k]).compensated_dph;
		offset += period;
	}
	benchmark::DoNotOptimize(sink);
	state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(n));
	state.counters["terms"] = static_cast<double>(cal().model.features.termCount());
	state.SetLabel(comp.kernelBuild());
}
/** step() sample by sample, the build chosen at run time (AVX2 where the CPU has it). */
static void BM_Compensate_Multipoint4(benchmark::State& state) { compensateMultipoint4(state, KernelBuild::Auto, false); }
BENCHMARK(BM_Compensate_Multipoint4)->Unit(benchmark::kMillisecond);
/** The same with the baseline x86-64 build forced (what a CPU without AVX2 runs). */
static void BM_Compensate_Multipoint4_Portable(benchmark::State& state)
{
	compensateMultipoint4(state, KernelBuild::Portable, false);
}
BENCHMARK(BM_Compensate_Multipoint4_Portable)->Unit(benchmark::kMillisecond);
/** stepBatch() over the whole run (times shifted into a buffer first, included in the time). */
static void BM_Compensate_Multipoint4_Batch(benchmark::State& state) { compensateMultipoint4(state, KernelBuild::Auto, true); }
BENCHMARK(BM_Compensate_Multipoint4_Batch)->Unit(benchmark::kMillisecond);

static void BM_Fit_Multipoint4(benchmark::State& state)
{
	const auto& r = rows();
	const std::size_t n = r.t.size(), total = static_cast<std::size_t>(state.range(0));
	const double period = r.t.back() + 1.0;
	ThermalFeatureSet fs = cal().model.features;  // 33 terms with the run's normalisation
	const std::size_t nt = fs.termCount(), ns = fs.signals().size();
	std::vector<double> f(nt), v(ns), rate(4);
	std::vector<int> cols(nt);
	for (std::size_t j = 0; j < nt; j++) cols[j] = static_cast<int>(j);
	double sink = 0;
	for (auto _ : state)
	{
		CausalRateTracker tr(4, cal().rate_estimator.window_s);
		StreamingQr ne(nt, cal().mean_bias_dph);
		double offset = 0;
		for (std::size_t done = 0; done < total;)
		{
			for (std::size_t k = 0; k < n && done < total; k++, done++)
			{
				const double* temp = &r.temp[4 * k];
				tr.push(r.t[k] + offset, temp);
				for (int i = 0; i < 4; i++) rate[i] = tr.rate(i);
				if (std::isnan(rate[0])) continue;
				fs.signalValues(temp, rate.data(), v.data());
				fs.features(v.data(), f.data(), false);
				ne.add(f.data(), r.rate[k]);
			}
			offset += period;
		}
		const LinearFit fit = solveBiasFit(ne, cols);
		sink += fit.coef_dph[1];
	}
	benchmark::DoNotOptimize(sink);
	state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(total));
	state.counters["peak_rss_MB"] = peakRssMB();
}
BENCHMARK(BM_Fit_Multipoint4)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
