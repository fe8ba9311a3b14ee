/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/GoldenSection.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/discrepancy/SimulatorCalibration.h>
#include <mrpt_fog/discrepancy/WhitenedRegression.h>
#include <mrpt_fog/metrics/LongRunVariance.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
using mrpt_fog::units::kNaN;

/** A parameter of the thermal network (fitted on the temperature residual). */
bool isTempSlot(const ParamSlot& s)
{
	if (s.id == "thermal_time_scale") return true;
	const auto* d = sim::descriptorOfCalibrationParameter(s.id);
	return d && d->identified_in == sim::IdentifiedIn::Temperature;
}

/** Finite-difference step of a slot: a typical size of the parameter. */
double fdStep(const ParamSlot& s, double v)
{
	double t = 1e-3;  // thermistor offsets [degC]
	if (s.id == "constant_bias_dph" || s.id == "thermal_time_scale") t = 0.01;
	else if (s.id == "sf_ref_C") t = 0.05;
	else if (const auto* d = sim::descriptorOfCalibrationParameter(s.id)) t = d->calibration.fd_step;
	return std::max(t, 1e-3 * std::abs(v));
}

/** Stacked temperature residual (offsets projected out when free); NaN entries give 0 and are
 * listed in `ok`. */
Eigen::VectorXd tempResidualVector(const FogSeries& run, const SimTrace& tr, bool offsets_free,
								   std::vector<double>* offset_shift = nullptr)
{
	const auto r = temperatureResidual(run, tr);
	const std::size_t n = run.size(), nt = r.size();
	Eigen::VectorXd v = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n * nt));
	if (offset_shift) offset_shift->assign(nt, 0.0);
	for (std::size_t i = 0; i < nt; ++i)
	{
		double mean = 0;
		std::size_t m = 0;
		for (double x : r[i])
			if (std::isfinite(x)) mean += x, ++m;
		mean = (offsets_free && m) ? mean / m : 0.0;
		if (offset_shift) (*offset_shift)[i] = mean;
		for (std::size_t k = 0; k < n; ++k)
			if (std::isfinite(r[i][k])) v(static_cast<Eigen::Index>(i * n + k)) = r[i][k] - mean;
	}
	return v;
}

/** Damped Gauss-Newton with a forward-difference Jacobian. `residual` evaluates a model. */
template <class F>
SimModel gaussNewton(SimModel m, const std::vector<ParamSlot>& slots, F residual, int max_iter, int& sims)
{
	if (slots.empty()) return m;
	Eigen::VectorXd r = residual(m);
	++sims;
	double rss = r.squaredNorm();
	for (int it = 0; it < max_iter; ++it)
	{
		Eigen::MatrixXd J(r.size(), static_cast<Eigen::Index>(slots.size()));
		for (std::size_t j = 0; j < slots.size(); ++j)
		{
			SimModel mj = m;
			const double v = getParam(m, slots[j]), h = fdStep(slots[j], v);
			setParam(mj, slots[j], v + h);
			const double hEff = getParam(mj, slots[j]) - v;
			J.col(static_cast<Eigen::Index>(j)) = hEff != 0 ? Eigen::VectorXd((residual(mj) - r) / hEff) : Eigen::VectorXd::Zero(r.size());
			++sims;
		}
		// r(p + d) ~ r + J d -> minimise |r + J d|
		const LsFit fit = leastSquares(J, -r);
		bool improved = false;
		for (double lambda = 1.0; lambda > 1e-3; lambda *= 0.5)
		{
			SimModel trial = m;
			for (std::size_t j = 0; j < slots.size(); ++j)
				setParam(trial, slots[j], getParam(m, slots[j]) + lambda * fit.coef(static_cast<Eigen::Index>(j)));
			// a step that leaves a parameter's valid domain (e.g. the midpoint offset beyond +-L/2,
			// which the simulator refuses) is rejected like a step that does not improve: halved
			Eigen::VectorXd rt;
			try
			{
				rt = residual(trial);
			}
			catch (const std::invalid_argument&)
			{
				continue;
			}
			++sims;
			if (rt.squaredNorm() < rss)
			{
				const double gain = (rss - rt.squaredNorm()) / std::max(rss, 1e-300);
				m = trial;
				r = rt;
				rss = rt.squaredNorm();
				improved = gain > 1e-9;
				break;
			}
		}
		if (!improved) break;
	}
	return m;
}

Eigen::MatrixXd biasJacobian(const SimModel& m, const std::vector<ParamSlot>& slots, const ChamberDrive& drive,
							 const FogSeries& run, const SimTrace& at, const std::vector<unsigned char>& rows, int& sims)
{
	const auto n = static_cast<Eigen::Index>(run.size());
	Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(slots.size()));
	for (std::size_t j = 0; j < slots.size(); ++j)
	{
		SimModel mj = m;
		const double v = getParam(m, slots[j]), h = fdStep(slots[j], v);
		setParam(mj, slots[j], v + h);
		const double hEff = getParam(mj, slots[j]) - v;
		const SimTrace tj = simulateOnRun(mj, drive, run);
		++sims;
		for (Eigen::Index k = 0; k < n; ++k)
		{
			const auto ku = static_cast<std::size_t>(k);
			if (rows[ku] && std::isfinite(tj.bias_dph[ku]) && std::isfinite(at.bias_dph[ku]) && hEff != 0)
				J(k, static_cast<Eigen::Index>(j)) = (tj.bias_dph[ku] - at.bias_dph[ku]) / hEff;
		}
	}
	return J;
}

std::vector<double> ciHalfWidths(const Eigen::MatrixXd& J, double s2)
{
	std::vector<double> out(static_cast<std::size_t>(J.cols()), kNaN);
	if (J.cols() == 0 || !std::isfinite(s2)) return out;
	const Eigen::MatrixXd JtJ = J.transpose() * J;
	Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(JtJ);
	if (cod.rank() < JtJ.cols()) return out;
	const Eigen::MatrixXd cov = s2 * cod.pseudoInverse();
	for (Eigen::Index j = 0; j < J.cols(); ++j) out[static_cast<std::size_t>(j)] = 1.96 * std::sqrt(std::max(0.0, cov(j, j)));
	return out;
}

void finish(SimCalibration& c, const FogSeries& run, const ChamberDrive& drive, const std::vector<double>& bias,
			const std::vector<unsigned char>& rows, bool offsets_free)
{
	c.trace = simulateOnRun(c.model, drive, run);
	++c.simulations;
	const auto rb = biasResidual(bias, c.trace, rows);
	std::size_t m = 0;
	for (std::size_t k = 0; k < rows.size(); ++k) m += rows[k] != 0;
	c.bias_rms_dph = m ? std::sqrt(rb.squaredNorm() / m) : kNaN;
	c.temp_rms_C = rmsOfFinite(temperatureResidual(run, c.trace));
	c.bias_jacobian = biasJacobian(c.model, c.bias_slots, drive, run, c.trace, rows, c.simulations);

	// 95 % intervals (see header): bias
	std::vector<double> rbUsed;
	for (std::size_t k = 0; k < rows.size(); ++k)
		if (rows[k]) rbUsed.push_back(rb(static_cast<Eigen::Index>(k)));
	c.bias_ci95_half = ciHalfWidths(c.bias_jacobian, batchMeansLongRunVariance({rbUsed}, BatchPooling::PooledBlocks));
	// temperatures: Jacobian of the stacked residual (offsets projected out when free)
	if (!c.temp_slots.empty())
	{
		const Eigen::VectorXd r0 = tempResidualVector(run, c.trace, offsets_free);
		Eigen::MatrixXd JT(r0.size(), static_cast<Eigen::Index>(c.temp_slots.size()));
		for (std::size_t j = 0; j < c.temp_slots.size(); ++j)
		{
			SimModel mj = c.model;
			const double v = getParam(c.model, c.temp_slots[j]), h = fdStep(c.temp_slots[j], v);
			setParam(mj, c.temp_slots[j], v + h);
			const double hEff = getParam(mj, c.temp_slots[j]) - v;
			const Eigen::VectorXd rj = tempResidualVector(run, simulateOnRun(mj, drive, run), offsets_free);
			++c.simulations;
			JT.col(static_cast<Eigen::Index>(j)) = hEff != 0 ? Eigen::VectorXd((rj - r0) / hEff) : Eigen::VectorXd::Zero(r0.size());
		}
		const auto rt = temperatureResidual(run, c.trace);
		std::vector<std::vector<double>> perThermistor;
		const std::size_t n = run.size();
		for (std::size_t i = 0; i < rt.size(); ++i)
		{
			std::vector<double> s;
			for (std::size_t k = 0; k < n; ++k)
				if (std::isfinite(rt[i][k])) s.push_back(r0(static_cast<Eigen::Index>(i * n + k)));
			perThermistor.push_back(std::move(s));
		}
		c.temp_ci95_half = ciHalfWidths(JT, batchMeansLongRunVariance(perThermistor, BatchPooling::PooledBlocks));
	}
}
}  // namespace

Eigen::VectorXd biasResidual(const std::vector<double>& measured, const SimTrace& tr, const std::vector<unsigned char>& rows)
{
	Eigen::VectorXd r = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(measured.size()));
	for (std::size_t k = 0; k < measured.size(); ++k)
		if (rows[k] && std::isfinite(tr.bias_dph[k]) && std::isfinite(measured[k]))
			r(static_cast<Eigen::Index>(k)) = measured[k] - tr.bias_dph[k];
	return r;
}

std::vector<std::vector<double>> temperatureResidual(const FogSeries& run, const SimTrace& tr)
{
	std::vector<std::vector<double>> r(run.thermistorCount(), std::vector<double>(run.size(), kNaN));
	for (std::size_t i = 0; i < run.thermistorCount(); ++i)
		for (std::size_t k = 0; k < run.size(); ++k)
			r[i][k] = run.temp_C[i][k] - tr.temp_C[i][k];  // NaN stays NaN
	return r;
}

double rmsOfFinite(const std::vector<std::vector<double>>& r)
{
	double s = 0;
	std::size_t m = 0;
	for (const auto& row : r)
		for (double x : row)
			if (std::isfinite(x)) s += x * x, ++m;
	return m ? std::sqrt(s / m) : kNaN;
}

SimCalibration calibrateSimulator(const SimModel& start, const std::vector<std::string>& free, const FogSeries& run,
								  const ChamberDrive& drive, const std::vector<double>& bias,
								  const std::vector<unsigned char>& rows)
{
	SimCalibration c;
	c.model = start;
	const auto slots = expandSlots(free, start);
	const bool offsetsFree = std::find(free.begin(), free.end(), "thermistor_offsets_C") != free.end();
	for (const auto& s : slots)
	{
		if (isTempSlot(s)) c.temp_slots.push_back(s);
		else if (s.id != "thermistor_offsets_C") c.bias_slots.push_back(s);
	}
	// 1. temperatures
	auto tempRes = [&](const SimModel& m) { return tempResidualVector(run, simulateOnRun(m, drive, run), offsetsFree); };
	c.model = gaussNewton(c.model, c.temp_slots, tempRes, 10, c.simulations);
	if (offsetsFree)
	{
		std::vector<double> shift;
		tempResidualVector(run, simulateOnRun(c.model, drive, run), true, &shift);
		++c.simulations;
		for (std::size_t i = 0; i < run.thermistorCount(); ++i)
			for (auto& t : c.model.device.thermistors)
				if (t.info.name == run.thermistors[i].name) t.offset_C += shift[i];
	}
	// 2. bias
	auto biasRes = [&](const SimModel& m) { return biasResidual(bias, simulateOnRun(m, drive, run), rows); };
	c.model = gaussNewton(c.model, c.bias_slots, biasRes, 6, c.simulations);
	finish(c, run, drive, bias, rows, offsetsFree);
	return c;
}

SimCalibration applyCalibration(const SimModel& calibrated, const std::vector<std::string>& free, const FogSeries& run,
								const ChamberDrive& drive, const std::vector<double>& bias,
								const std::vector<unsigned char>& rows)
{
	SimCalibration c;
	c.model = calibrated;
	for (const auto& s : expandSlots(free, calibrated))
		if (!isTempSlot(s) && s.id != "thermistor_offsets_C") c.bias_slots.push_back(s);
	const ParamSlot constant{"constant_bias_dph", 0};
	auto biasRes = [&](const SimModel& m) { return biasResidual(bias, simulateOnRun(m, drive, run), rows); };
	c.model = gaussNewton(c.model, {constant}, biasRes, 2, c.simulations);
	finish(c, run, drive, bias, rows, false);
	return c;
}

ProjectedThermal projectThermalOnLogDrive(const SimModel& start, const std::vector<std::string>& free,
										  const ChamberDrive& drive, const FogSeries& run)
{
	ProjectedThermal out;
	out.model = start;
	if (drive.source != DriveSource::MeasuredLog)
	{
		out.drive = drive;
		return out;
	}
	// The search reconstructs on knots 3x coarser (its cost grows with the square of the knots),
	// with the regularisation weight chosen once by GCV at the start; the final drive uses the
	// default knots.
	AirReconstructionOptions fast;
	fast.knot_spacing_s = 3 * AirReconstructionOptions{}.knot_spacing_s;
	fast.uncertainty = false;
	fast.lambda = reconstructDriveWith(drive, start, run, fast).air.lambda;
	auto objective = [&](const SimModel& m)
	{
		const ChamberDrive d = reconstructDriveWith(drive, m, run, fast);
		const auto r = temperatureResidual(run, simulateOnRun(m, d, run));
		out.simulations += 3;
		double ss = 0, n = 0;
		for (const auto& ri : r)
		{
			double mu = 0, c = 0;
			for (double v : ri)
				if (std::isfinite(v))
				{
					mu += v;
					c++;
				}
			if (c == 0) continue;
			mu /= c;
			for (double v : ri)
				if (std::isfinite(v))
				{
					ss += (v - mu) * (v - mu);
					n++;
				}
		}
		return n > 0 ? std::sqrt(ss / n) : INFINITY;
	};
	// one parameter set to its best value on [lo, hi], the others held
	auto golden = [&](auto set, double lo, double hi) {
		const double best = goldenSectionMinimum(
			[&](double x) {
				SimModel m = out.model;
				set(m, x);
				return objective(m);
			},
			lo, hi, 12);
		set(out.model, best);
	};
	const bool scaleFree = std::find(free.begin(), free.end(), "thermal_time_scale") != free.end();
	const bool powerFree = std::find(free.begin(), free.end(), "electronics_power_W") != free.end() &&
						   start.effects.count("heat_source") > 0;
	const double p0 = std::max(start.device.thermal.electronics_power_W, 1e-3);
	for (int sweep = 0; sweep < 2; ++sweep)
	{
		if (scaleFree)
			golden([](SimModel& m, double x) { m.thermal_time_scale = std::exp(x); }, std::log(0.2), std::log(5.0));
		if (powerFree)
			golden([](SimModel& m, double x) { m.device.thermal.electronics_power_W = x; }, 0.2 * p0, 3.0 * p0);
		if (!scaleFree && !powerFree) break;
	}
	out.temp_rms_C = objective(out.model);
	out.drive = reconstructDriveWith(drive, out.model, run);
	out.simulations += 2;
	return out;
}

}  // namespace mrpt_fog::discrepancy
