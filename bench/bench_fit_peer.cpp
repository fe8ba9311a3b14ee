/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The least-squares core (streaming QR) on a stored design matrix, for the NumPy peer comparison
 * (scripts/bench_numpy_peer.py): the 33-term multipoint design matrix of a synthetic chamber run
 * (normalised features, causal rates), repeated `kCycles` times.
 *
 *   bench_fit_peer --export DIR [PRESET]   writes DIR/X.f64 (rows x terms, row-major), DIR/y.f64,
 *                                 DIR/shape.txt and DIR/coef_mrpt_fog.txt (our coefficients) for
 *                                 PRESET (default multipoint: 33 terms), then exits
 *   bench_fit_peer                runs BM_FitDesignMatrix_Multipoint4 (items = rows) */
#include <benchmark/benchmark.h>
#include <mrpt_fog/model/BiasFit.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/RateEstimator.h>

#include <cstdio>
#include <cstring>
#include <fstream>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
constexpr int kCycles = 10;

struct Design
{
	std::size_t rows = 0, cols = 0;
	std::vector<double> X, y;  // row-major
	double y_ref = 0;
};

Design makeDesign(const std::string& preset)
{
	{
		const FogSeries s = fogtest::makeCoilRun("A", 7);
		FitOptions o;
		o.selection = TermSelection::None;
		o.fallbacks = false;
		const Calibration cal = fitCalibration({s}, preset, o);
		const std::size_t nth = cal.model.features.thermistors().size();
		const auto& fs = cal.model.features;
		Design d;
		d.cols = fs.termCount();
		d.y_ref = cal.mean_bias_dph;
		CausalRateTracker tr(nth, cal.rate_estimator.window_s);
		std::vector<double> temp(nth), rate(nth), v(fs.signals().size()), f(d.cols);
		const double period = s.time_s.back() + 1.0;
		for (int cyc = 0; cyc < kCycles; cyc++)
			for (std::size_t k = 0; k < s.size(); k++)
			{
				for (std::size_t i = 0; i < nth; i++) temp[i] = s.temp_C[s.thermistorIndex(fs.thermistors()[i])][k];
				tr.push(s.time_s[k] + cyc * period, temp.data());
				bool ok = true;
				for (std::size_t i = 0; i < nth; i++) ok &= !std::isnan(rate[i] = tr.rate(i));
				if (!ok) continue;
				fs.signalValues(temp.data(), rate.data(), v.data());
				fs.features(v.data(), f.data(), false);
				d.X.insert(d.X.end(), f.begin(), f.end());
				d.y.push_back(s.rate_dph[2][k]);
				d.rows++;
			}
		return d;
	}
}

const Design& design()
{
	static const Design d = makeDesign("multipoint");
	return d;
}

Eigen::VectorXd fit(const Design& d)
{
	// Two passes, as fitCalibration does: feature means first (the accumulation reference).
	std::vector<double> mean(d.cols, 0.0);
	for (std::size_t r = 0; r < d.rows; r++)
		for (std::size_t j = 0; j < d.cols; j++) mean[j] += d.X[r * d.cols + j];
	for (double& m : mean) m /= static_cast<double>(d.rows);
	StreamingQr qr(d.cols, d.y_ref, mean);
	for (std::size_t r = 0; r < d.rows; r++) qr.add(&d.X[r * d.cols], d.y[r]);
	std::vector<int> cols(d.cols);
	for (std::size_t j = 0; j < d.cols; j++) cols[j] = static_cast<int>(j);
	return solveBiasFit(qr, cols).coef_dph;
}

void writeRaw(const std::string& path, const std::vector<double>& v)
{
	std::ofstream o(path, std::ios::binary);
	o.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
	if (!o) throw std::runtime_error("cannot write " + path);
}
}  // namespace

static void BM_FitDesignMatrix_Multipoint4(benchmark::State& state)
{
	const Design& d = design();
	double sink = 0;
	for (auto _ : state) sink += fit(d)[1];
	benchmark::DoNotOptimize(sink);
	state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(d.rows));
	state.counters["rows"] = static_cast<double>(d.rows);
	state.counters["cols"] = static_cast<double>(d.cols);
}
BENCHMARK(BM_FitDesignMatrix_Multipoint4)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv)
{
	if ((argc == 3 || argc == 4) && std::strcmp(argv[1], "--export") == 0)
	{
		const std::string dir = argv[2];
		const Design d = makeDesign(argc == 4 ? argv[3] : "multipoint");
		writeRaw(dir + "/X.f64", d.X);
		writeRaw(dir + "/y.f64", d.y);
		std::ofstream(dir + "/shape.txt") << d.rows << " " << d.cols << "\n";
		const Eigen::VectorXd c = fit(d);
		std::ofstream o(dir + "/coef_mrpt_fog.txt");
		o.precision(17);
		for (Eigen::Index j = 0; j < c.size(); j++) o << c[j] << "\n";
		std::printf("exported %zu x %zu design matrix to %s\n", d.rows, d.cols, dir.c_str());
		return 0;
	}
	benchmark::Initialize(&argc, argv);
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}
