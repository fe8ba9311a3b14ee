/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/ChamberReconstruction.h>
#include <mrpt_fog/metrics/LongRunVariance.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
double AirReconstruction::airAt(double t_s) const
{
	if (knot_time_s.empty()) return NAN;
	if (t_s <= knot_time_s.front()) return knot_air_C.front();
	if (t_s >= knot_time_s.back()) return knot_air_C.back();
	const auto it = std::upper_bound(knot_time_s.begin(), knot_time_s.end(), t_s);
	const std::size_t j = static_cast<std::size_t>(it - knot_time_s.begin());
	const double w = (t_s - knot_time_s[j - 1]) / (knot_time_s[j] - knot_time_s[j - 1]);
	return knot_air_C[j - 1] + w * (knot_air_C[j] - knot_air_C[j - 1]);
}

namespace
{
/** Noise-free thermistor readings (device order) at every simulator step. */
std::vector<std::vector<double>> simulateThermistors(sim::FogDevice dev, const sim::EffectSet& effects, double time_scale,
													 const std::vector<sim::ChamberState>& states, double rate_hz)
{
	dev = dev.withoutNoise();
	dev.thermal.scaleHeatCapacities(time_scale);
	sim::FogSimulator fog(dev, effects, 1);
	const double dt = 1.0 / rate_hz;
	std::vector<std::vector<double>> out(states.size());
	for (std::size_t j = 0; j < states.size(); ++j)
	{
		const sim::FogSample s = j == 0 ? fog.start(states[0], sim::InitialThermalState::Steady) : fog.advance(dt, states[j]);
		out[j] = s.temp_C;
	}
	return out;
}
}  // namespace

AirReconstruction reconstructChamberAir(const sim::FogDevice& device, const sim::EffectSet& effects, double thermal_time_scale,
										const std::vector<sim::ChamberState>& states, double rate_hz, const FogSeries& run,
										const std::vector<std::size_t>& sim_index, const AirReconstructionOptions& opt)
{
	const std::size_t nSim = states.size();
	if (nSim < 2) throw std::invalid_argument("air reconstruction: the run is shorter than two simulator steps");
	std::vector<std::size_t> devIndex;
	for (const auto& th : run.thermistors)
	{
		std::size_t found = device.thermistors.size();
		for (std::size_t j = 0; j < device.thermistors.size(); ++j)
			if (device.thermistors[j].info.name == th.name) found = j;
		if (found == device.thermistors.size())
			throw std::invalid_argument("run thermistor '" + th.name + "' is not a thermistor of the simulated device");
		devIndex.push_back(found);
	}
	// Knot grid: q simulator steps per knot interval, K intervals.
	const double dt = 1.0 / rate_hz;
	std::size_t q = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(opt.knot_spacing_s / dt)));
	std::size_t K = (nSim - 1 + q - 1) / q;
	if (K > opt.max_knots)
	{
		q = (nSim - 1 + opt.max_knots - 1) / opt.max_knots;
		K = (nSim - 1 + q - 1) / q;
	}
	// Baseline (0 C air, the run's power) and the unit-ramp response from rest.
	std::vector<sim::ChamberState> base = states, ramp(nSim);
	for (auto& s : base) s.air_C = 0.0;
	for (std::size_t j = 0; j < nSim; ++j)
	{
		ramp[j].power_on = false;
		ramp[j].air_C = std::min(1.0, static_cast<double>(j) / static_cast<double>(q));
	}
	const auto B = simulateThermistors(device, effects, thermal_time_scale, base, rate_hz);
	const auto U = simulateThermistors(device, effects, thermal_time_scale, ramp, rate_hz);

	// Rows.
	struct Row
	{
		std::size_t therm, step;
		double y;
	};
	std::vector<Row> rows;
	std::vector<std::size_t> rowsPerTherm;
	for (std::size_t i = 0; i < run.thermistorCount(); ++i)
	{
		std::vector<std::size_t> ks;
		for (std::size_t k = 0; k < run.size(); ++k)
			if (std::isfinite(run.temp_C[i][k]) && sim_index[k] < nSim) ks.push_back(k);
		const std::size_t stride = std::max<std::size_t>(1, (ks.size() + opt.max_rows_per_thermistor - 1) / opt.max_rows_per_thermistor);
		std::size_t used = 0;
		for (std::size_t a = 0; a < ks.size(); a += stride)
		{
			const std::size_t k = ks[a], j = sim_index[k];
			rows.push_back({i, j, run.temp_C[i][k] - B[j][devIndex[i]]});
			used++;
		}
		rowsPerTherm.push_back(used);
	}
	const auto n = static_cast<Eigen::Index>(rows.size());
	const auto p = static_cast<Eigen::Index>(K + 1);
	if (n < p) throw std::invalid_argument("air reconstruction: too few thermistor readings for " + std::to_string(K + 1) + " air knots");
	Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, p);
	Eigen::VectorXd y(n);
	for (Eigen::Index r = 0; r < n; ++r)
	{
		const Row& row = rows[static_cast<std::size_t>(r)];
		G(r, 0) = 1.0;
		y(r) = row.y;
		for (std::size_t j = 1; j <= K; ++j)
		{
			const std::size_t start = (j - 1) * q;
			if (row.step < start) break;
			G(r, static_cast<Eigen::Index>(j)) = U[row.step - start][devIndex[row.therm]] - U[0][devIndex[row.therm]];
		}
	}
	// Penalty on d_j - d_{j-1} (j >= 2): P = Dd' Dd, Dd the knot differences (column j - 2 of Dd'
	// is e_j - e_{j-1}); both are filled here, P directly (tridiagonal; no p x p product).
	Eigen::MatrixXd differencesT = Eigen::MatrixXd::Zero(p, std::max<Eigen::Index>(p - 2, 0));
	Eigen::MatrixXd P = Eigen::MatrixXd::Zero(p, p);
	for (Eigen::Index j = 2; j < p; ++j)
	{
		differencesT(j, j - 2) = 1.0;
		differencesT(j - 1, j - 2) = -1.0;
		P(j, j) += 1;
		P(j - 1, j - 1) += 1;
		P(j, j - 1) -= 1;
		P(j - 1, j) -= 1;
	}
	// G'G: only one triangle is computed (A is symmetric), then mirrored. A row at simulator step
	// s has no response to the knots after s (zeros from column s / q + 2 on), and the rows of a
	// thermistor are in time order: each chunk of rows updates only the columns its rows reach.
	Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, p);
	constexpr Eigen::Index kChunkRows = 256;
	for (Eigen::Index r0 = 0; r0 < n; r0 += kChunkRows)
	{
		const Eigen::Index len = std::min(kChunkRows, n - r0);
		Eigen::Index cols = 1;
		for (Eigen::Index r = r0; r < r0 + len; ++r)
			cols = std::max(cols, std::min<Eigen::Index>(p, static_cast<Eigen::Index>(rows[static_cast<std::size_t>(r)].step / q) + 2));
		A.topLeftCorner(cols, cols).selfadjointView<Eigen::Lower>().rankUpdate(G.block(r0, 0, len, cols).transpose());
	}
	A.triangularView<Eigen::StrictlyUpper>() = A.transpose();
	const Eigen::VectorXd g = G.transpose() * y;
	const double scale = A.diagonal().mean();
	AirReconstruction best;
	double bestGcv = INFINITY;
	Eigen::VectorXd bestX;
	Eigen::MatrixXd bestInv;
	std::vector<double> lambdas;
	if (opt.lambda > 0)
		lambdas.push_back(opt.lambda);
	else
		for (int e = -8; e <= 2; ++e) lambdas.push_back(scale * std::pow(10.0, e));
	// GCV's trace(H) = trace(inv A) with inv = (A + lambda P)^-1: inv A = I - lambda inv P, and
	// P = Dd' Dd (Dd: the knot differences), so trace(inv A) = p - lambda sum_c b_c' inv b_c over
	// the columns b_c of Dd', each b' inv b = |D^-1/2 L^-1 Pm b|^2 from the factorisation
	// A + lambda P = Pm' L D L' Pm: one triangular solve with p - 2 right-hand sides instead of
	// the whole inverse. The inverse itself is formed once, for the chosen weight (uncertainty).
	auto traceH = [&](const Eigen::LDLT<Eigen::MatrixXd>& ldlt, double lambda) -> double
	{
		const Eigen::VectorXd& d = ldlt.vectorD();
		if (!(d.minCoeff() > 0)) return ldlt.solve(Eigen::MatrixXd::Identity(p, p)).cwiseProduct(A).sum();
		if (p < 3) return static_cast<double>(p);
		Eigen::MatrixXd B = ldlt.transpositionsP() * differencesT;
		ldlt.matrixL().solveInPlace(B);
		double tr_invP = 0.0;
		for (Eigen::Index i = 0; i < p; ++i) tr_invP += B.row(i).squaredNorm() / d(i);
		return static_cast<double>(p) - lambda * tr_invP;
	};
	for (double lambda : lambdas)
	{
		const Eigen::LDLT<Eigen::MatrixXd> ldlt(A + lambda * P);
		if (ldlt.info() != Eigen::Success) continue;
		const Eigen::VectorXd x = ldlt.solve(g);
		if (!x.allFinite()) continue;
		double gcv = 0;
		if (lambdas.size() > 1)
		{
			const double trH = traceH(ldlt, lambda);
			const double rss = (y - G * x).squaredNorm();
			const double denom = static_cast<double>(n) - trH;
			if (!(denom > 0)) continue;
			gcv = static_cast<double>(n) * rss / (denom * denom);
		}
		if (gcv < bestGcv)
		{
			bestGcv = gcv;
			best.lambda = lambda;
			bestX = x;
		}
	}
	if (bestX.size() != 0 && opt.uncertainty)
	{
		const Eigen::LDLT<Eigen::MatrixXd> ldlt(A + best.lambda * P);
		bestInv = ldlt.solve(Eigen::MatrixXd::Identity(p, p));
	}
	if (bestX.size() == 0) throw std::invalid_argument("air reconstruction: the thermal inverse is singular for every regularisation weight");
	const Eigen::VectorXd res = y - G * bestX;
	best.fit_rms_C = std::sqrt(res.squaredNorm() / static_cast<double>(n));
	// Long-run residual variance by batch means, per thermistor (rows are in time order within one).
	std::vector<std::vector<double>> perThermistor;
	Eigen::Index r0 = 0;
	for (std::size_t m : rowsPerTherm)
	{
		perThermistor.emplace_back(res.data() + r0, res.data() + r0 + static_cast<Eigen::Index>(m));
		r0 += static_cast<Eigen::Index>(m);
	}
	const double s2_batch = batchMeansLongRunVariance(perThermistor, BatchPooling::MeanOfSeries);
	const double s2 = std::isfinite(s2_batch) ? s2_batch : res.squaredNorm() / static_cast<double>(n);
	if (!opt.uncertainty || bestInv.size() == 0)
	{
		double air0 = bestX(0);
		for (std::size_t m = 0; m <= K; ++m)
		{
			if (m > 0) air0 += bestX(static_cast<Eigen::Index>(m));
			best.knot_time_s.push_back(static_cast<double>(m * q) * dt);
			best.knot_air_C.push_back(air0);
			best.knot_ci95_half_C.push_back(NAN);
		}
		best.mean_ci95_half_C = best.max_ci95_half_C = NAN;
		return best;
	}
	// The air at knot m is L_m' x with L_m = (1, ..., 1 [m + 1 ones], 0, ...): variance
	// L_m' C L_m = v_{m-1} + 2 sum_{i<m} C_im + C_mm, with C = s2 inv (symmetric). O(p^2).
	double air = bestX(0);
	double v = 0.0;
	for (std::size_t m = 0; m <= K; ++m)
	{
		const auto mi = static_cast<Eigen::Index>(m);
		if (m > 0) air += bestX(mi);
		v += 2.0 * bestInv.col(mi).head(mi).sum() + bestInv(mi, mi);
		best.knot_time_s.push_back(static_cast<double>(m * q) * dt);
		best.knot_air_C.push_back(air);
		best.knot_ci95_half_C.push_back(1.96 * std::sqrt(std::max(s2 * v, 0.0)));
	}
	double sum = 0;
	for (double h : best.knot_ci95_half_C)
	{
		sum += h;
		best.max_ci95_half_C = std::max(best.max_ci95_half_C, h);
	}
	best.mean_ci95_half_C = sum / static_cast<double>(best.knot_ci95_half_C.size());
	return best;
}

}  // namespace mrpt_fog::discrepancy
