/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/containers/yaml.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/ErrorText.h>
#include <mrpt_fog/common/Utf8.h>
#include <mrpt_fog/common/YamlGuard.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/obs/Units.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
constexpr const char* kFormat = "mrpt_fog_calibration";
constexpr int kVersion = 2;  //!< written; version 1 (single axis, bias only) is still read
/** Written instead of kVersion when an axis holds what a version-2 reader cannot apply, so that
 * such a build says so instead of failing on a term or silently ignoring a section. Version 3 =
 * version 2 + lag signals (dTlag/dt, LagFilter.h) with the bias section's `lag_filter` (the
 * lag's discretisation and warm start), hysteresis signals (hyst(a,...), HysteresisFilter.h)
 * with the bias section's `hysteresis_filter` (the operators' warm start and the branch's dead
 * band), and/or the axis' `magnetic` section (MagneticModel.h). Files without any of them are
 * written as version 2. */
constexpr int kVersionExtended = 3;
constexpr const char* kLagFilter = "first_order_hold, warm_start_first_reading";
/** The hysteresis operators this build runs (HysteresisFilter.h); a file naming others is refused. */
std::string hysteresisFilterText()
{
	return "play_and_branch, warm_start_first_reading_h0, branch_dead_band_" + formatValue("%g", kHysteresisDeadBand_C) + "C";
}

template <class Pred>
bool readsSignal(const Calibration& cal, Pred pred)
{
	const auto reads = [&](const BiasModel& m) {
		for (const auto& sig : m.features.signals())
			if (pred(sig)) return true;
		return false;
	};
	bool any = reads(cal.model) || (cal.startup && reads(*cal.startup));
	for (const auto& f : cal.fallbacks) any |= reads(f);
	return any;
}
bool readsLags(const Calibration& cal)
{
	return readsSignal(cal, [](const ThermalSignal& s) { return s.isLag(); });
}
bool readsHysteresis(const Calibration& cal)
{
	return readsSignal(cal, [](const ThermalSignal& s) { return s.isHysteresis(); });
}
// Plausibility limits of loaded values (a coef_dph of 1e308 compensated to -2e307
// deg/h). Every term is z^k with |z| <= 1 after clamping, so a coefficient bounds its term's
// contribution to the bias: 1e6 deg/h (278 deg/s) is beyond any gyro's bias.
constexpr double kMaxCoef_dph = 1e6;
constexpr const char* kCoefWhy = "a bias term of more than 1e6 deg/h is no gyro's";
constexpr double kMaxSignal_C = 1000.0;  // temperatures and differences [degC]
constexpr double kMaxSignalRate_Cps = 100.0;  // temperature rates [degC/s]
// Scale factor: a term of more than 1e5 ppm (10 %) and warm-up amplitudes beyond 1e6 deg/h
// are no FOG's; a warm-up time constant beyond 10 days is not a warm-up.
constexpr double kMaxCoef_ppm = 1e5;
constexpr const char* kPpmWhy = "a scale-factor term of more than 1e5 ppm is no FOG's";
constexpr double kMaxWarmupTau_s = 864000.0;
constexpr double kMaxSamples = 1e15;  // counts of samples, segments, turn-ons: far beyond any log

std::string num(double v)
{
	if (std::isnan(v)) return ".nan";
	if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
	return formatValue("%.17g", v);
}

std::string str(const std::string& s)
{
	std::string o = "\"";
	for (char c : s)
	{
		if (c == '"' || c == '\\') o += '\\';
		if (c == '\n' || c == '\r') c = ' ';
		o += c;
	}
	return o + "\"";
}

void writeFigures(std::ostringstream& o, const std::string& key, const FitFigures& f, const std::string& ind)
{
	o << ind << key << ":\n";
	o << ind << "  label: " << str(f.label) << "\n";
	o << ind << "  valid: " << (f.valid ? "true" : "false") << "\n";
	o << ind << "  samples: " << f.samples << "\n";
	o << ind << "  tau_s: " << num(f.tau_s) << "\n";
	o << ind << "  rms_dph: " << num(f.rms_dph) << "  # compensated, about its mean [deg/h]\n";
	o << ind << "  stability_dph: " << num(f.stability_dph) << "  # std of tau-s averages, compensated [deg/h]\n";
	o << ind << "  range_dph: " << num(f.range_dph) << "  # max - min of tau-s averages, compensated [deg/h]\n";
	o << ind << "  raw_stability_dph: " << num(f.raw_stability_dph) << "\n";
	o << ind << "  raw_range_dph: " << num(f.raw_range_dph) << "\n";
}

void writeMatrix(std::ostringstream& o, const Eigen::MatrixXd& m, const std::string& ind)
{
	for (Eigen::Index r = 0; r < m.rows(); r++)
	{
		o << ind << "- [";
		for (Eigen::Index c = 0; c < m.cols(); c++) o << (c ? ", " : "") << num(m(r, c));
		o << "]\n";
	}
}

void writeScaleFactor(std::ostringstream& o, const ScaleFactorModel& m, const std::string& ind)
{
	o << ind << "scale_factor:  # omega = (raw - bias) / (1 + 1e-6 s_ppm), s_ppm = sum coef_ppm[k] z^k\n";
	o << ind << "  thermistor: " << str(m.thermistor) << "\n";
	if (!m.thermistors.empty())  // optional: the model reads the mean of these
	{
		o << ind << "  thermistors: [";
		for (std::size_t i = 0; i < m.thermistors.size(); i++) o << (i ? ", " : "") << str(m.thermistors[i]);
		o << "]  # T = " << (m.weights.empty() ? "mean of these readings" : "sum of weights x these readings") << "\n";
	}
	if (!m.weights.empty())
	{
		o << ind << "  weights: [";
		for (std::size_t i = 0; i < m.weights.size(); i++) o << (i ? ", " : "") << num(m.weights[i]);
		o << "]  # of thermistors, summing to 1: the coil temperature the scale factor follows\n";
	}
	o << ind << "  centre_C: " << num(m.centre_C) << "  # z = (clamp(T, min_C, max_C) - centre_C) / scale_C\n";
	o << ind << "  scale_C: " << num(m.scale_C) << "\n";
	o << ind << "  min_C: " << num(m.min_C) << "  # calibrated range: T is clamped to [min_C, max_C]\n";
	o << ind << "  max_C: " << num(m.max_C) << "\n";
	o << ind << "  coef_ppm: [";
	for (std::size_t k = 0; k < m.coef_ppm.size(); k++) o << (k ? ", " : "") << num(m.coef_ppm[k]);
	o << "]  # of z^0, z^1, ... [ppm]\n";
	o << ind << "  covariance_ppm2:" << (m.covariance_ppm2.rows() == 0 ? " []" : "") << "\n";
	writeMatrix(o, m.covariance_ppm2, ind + "    ");
	o << ind << "  slope_ppm_per_C: " << num(m.slope_ppm_per_C)
	  << "  # (s(max_C) - s(min_C)) / (max_C - min_C) [ppm/degC]\n";
	o << ind << "  slope_ci95_ppm_per_C: [" << num(m.slope_ci95_lo_ppm_per_C) << ", " << num(m.slope_ci95_hi_ppm_per_C)
	  << "]  # 95 % interval: noise and the thermistors' disagreement on the coil temperature\n";
	if (m.slope_thermistors > 0)
	{
		o << ind << "  slope_noise_ci95_ppm_per_C: [" << num(m.slope_noise_ci95_lo_ppm_per_C) << ", "
		  << num(m.slope_noise_ci95_hi_ppm_per_C) << "]  # measurement noise only\n";
		o << ind << "  slope_thermistor_range_ppm_per_C: [" << num(m.slope_thermistor_min_ppm_per_C) << ", "
		  << num(m.slope_thermistor_max_ppm_per_C) << "]  # slope against each of " << m.slope_thermistors
		  << " thermistor(s)\n";
		o << ind << "  slope_thermistors: " << m.slope_thermistors << "\n";
	}
	o << ind << "  table_rate_abs_dph: [" << num(m.table_rate_min_abs_dph) << ", " << num(m.table_rate_max_abs_dph)
	  << "]  # |applied rate| range of the segments used [deg/h]\n";
	o << ind << "  segments: " << m.segments << "\n";
	o << ind << "  samples: " << m.samples << "\n";
	o << ind << "  rms_in_sample_ppm: " << num(m.rms_in_sample_ppm) << "\n";
	o << ind << "  rms_held_out_ppm: " << num(m.rms_held_out_ppm) << "\n";
	o << ind << "  held_out_label: " << str(m.held_out_label) << "\n";
}

void writeMagnetic(std::ostringstream& o, const MagneticModel& m, const std::string& ind)
{
	o << ind << "magnetic:  # bias += dph_per_uT * field_uT (applied axial magnetic field [uT]); version 3\n";
	o << ind << "  dph_per_uT: " << num(m.dph_per_uT) << "  # [deg/h per uT]\n";
	o << ind << "  dph_per_uT_std: " << num(m.dph_per_uT_std) << "  # standard error [deg/h per uT]\n";
	o << ind << "  field_range_uT: [" << num(m.field_min_uT) << ", " << num(m.field_max_uT)
	  << "]  # applied field seen in the fit [uT]\n";
	o << ind << "  samples: " << m.samples << "\n";
}

void writeWarmup(std::ostringstream& o, const WarmupModel& w, const std::string& ind)
{
	o << ind << "warmup:  # bias += amplitude_dph * exp(-(t - t_on) / tau_s) after each turn-on t_on\n";
	o << ind << "  amplitude_dph: " << num(w.amplitude_dph) << "\n";
	o << ind << "  tau_s: " << num(w.tau_s) << "\n";
	o << ind << "  amplitude_std_dph: " << num(w.amplitude_std_dph) << "\n";
	o << ind << "  tau_std_s: " << num(w.tau_std_s) << "\n";
	o << ind << "  fitted_span_s: " << num(w.fitted_span_s) << "  # time after the turn-on covered by the fit [s]\n";
	o << ind << "  turn_ons: " << w.turn_ons << "\n";
	o << ind << "  samples: " << w.samples << "\n";
	o << ind << "  rms_before_dph: " << num(w.rms_before_dph) << "  # bias model alone, fitted span [deg/h]\n";
	o << ind << "  rms_after_dph: " << num(w.rms_after_dph) << "  # with the warm-up term [deg/h]\n";
	if (w.hasSecondTerm())
	{
		o << ind << "  amplitude2_dph: " << num(w.amplitude2_dph) << "  # second term: + amplitude2_dph * exp(-(t - t_on) / tau2_s)\n";
		o << ind << "  tau2_s: " << num(w.tau2_s) << "\n";
		o << ind << "  amplitude2_std_dph: " << num(w.amplitude2_std_dph) << "\n";
		o << ind << "  tau2_std_s: " << num(w.tau2_std_s) << "\n";
	}
	if (w.startup_samples > 0 || w.startup_offset_dph != 0.0)  // optional: files without it read as before
	{
		o << ind << "  startup_offset_dph: " << num(w.startup_offset_dph)
		  << "  # added while the rate-free start-up model runs in the first rate window after a turn-on\n";
		o << ind << "  startup_offset_std_dph: " << num(w.startup_offset_std_dph) << "\n";
		o << ind << "  startup_samples: " << w.startup_samples << "\n";
	}
}

void writeModel(std::ostringstream& o, const BiasModel& m, const std::string& ind)
{
	const auto& fs = m.features;
	o << ind << "dropped: " << str(m.dropped) << "\n";
	o << ind << "coefficient_unit: \"deg/h\"\n";
	o << ind << "feature: \"term = z^k with z = (signal - centre) / scale; bias_dph = sum coef_dph * term\"\n";
	// A constant-only model (e.g. the fallback of a one-thermistor calibration) has no signals:
	// an empty flow list, since an empty block "signals:" reads back as null.
	o << ind << "signals:" << (fs.signals().empty() ? " []" : "") << "\n";
	for (std::size_t s = 0; s < fs.signals().size(); s++)
	{
		const auto& nm = fs.normalisation()[s];
		o << ind << "  - name: " << str(fs.signals()[s].name()) << "\n";
		o << ind << "    unit: " << str(fs.signals()[s].unit()) << "\n";
		o << ind << "    centre: " << num(nm.centre) << "\n";
		o << ind << "    scale: " << num(nm.scale) << "\n";
		o << ind << "    min: " << num(nm.min) << "  # calibrated range: inputs are clamped to [min, max]\n";
		o << ind << "    max: " << num(nm.max) << "\n";
	}
	o << ind << "terms:\n";
	for (std::size_t i = 0; i < fs.termCount(); i++)
	{
		const double var = (m.covariance.rows() == static_cast<Eigen::Index>(fs.termCount()))
							   ? m.covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i))
							   : std::numeric_limits<double>::quiet_NaN();
		o << ind << "  - name: " << str(fs.terms()[i].name()) << "\n";
		o << ind << "    coef_dph: " << num(m.coef_dph[i]) << "\n";
		o << ind << "    std_dph: " << num(std::sqrt(std::max(var, 0.0))) << "\n";
	}
	o << ind << "covariance_dph2:\n";
	writeMatrix(o, m.covariance, ind + "  ");
	o << ind << "fit:\n";
	o << ind << "  samples: " << m.samples << "\n";
	o << ind << "  ridge: " << num(m.ridge) << "  # relative to the unit-diagonal (equilibrated) system\n";
	o << ind << "  condition_number: " << num(m.condition_number) << "  # centred, equilibrated normal matrix\n";
	o << ind << "  numerical_rank: " << m.numerical_rank << "\n";
	o << ind << "  effective_dof: " << num(m.effective_dof) << "\n";
	o << ind << "  rms_in_sample_dph: " << num(m.rms_in_sample_dph) << "  # in-sample residual RMS [deg/h]\n";
	o << ind << "  rms_held_out_dph: " << num(m.rms_held_out_dph) << "  # cross-validated residual RMS [deg/h]\n";
}

using mrpt::containers::yaml;

/** Field access with "<source>: <path>: <reason>" errors. */
struct Reader
{
	std::string source;
	[[noreturn]] void fail(const std::string& path, const std::string& why) const
	{
		throw std::invalid_argument(source + ": " + path + ": " + why);
	}
	yaml child(const yaml& n, const std::string& key, const std::string& path) const
	{
		if (!n.isMap()) fail(path, "expected a map");
		if (!n.has(key)) fail(path + "." + key, "missing");
		return n[key];
	}
	double number(const yaml& n, const std::string& key, const std::string& path) const
	{
		const yaml c = child(n, key, path);
		try
		{
			const std::string s = c.as<std::string>();
			if (s == ".nan") return std::numeric_limits<double>::quiet_NaN();
			if (s == ".inf") return std::numeric_limits<double>::infinity();
			if (s == "-.inf") return -std::numeric_limits<double>::infinity();
			std::size_t used = 0;
			const double v = std::stod(s, &used);
			if (used != s.size()) throw std::invalid_argument("trailing text");
			return v;
		}
		catch (const std::exception&)
		{
			fail(path + "." + key, "not a number");
		}
	}
	double finite(const yaml& n, const std::string& key, const std::string& path) const
	{
		const double v = number(n, key, path);
		if (!std::isfinite(v)) fail(path + "." + key, "must be a finite number");
		return v;
	}
	/** A finite number within [lo, hi] (physically plausible), else "<field>: <v> is outside ...". */
	double bounded(const yaml& n, const std::string& key, const std::string& path, double lo, double hi,
				   const char* why) const
	{
		const double v = finite(n, key, path);
		if (v < lo || v > hi) fail(path + "." + key, num(v) + " is outside [" + num(lo) + ", " + num(hi) + "] (" + why + ")");
		return v;
	}
	/** A whole number within [lo, hi] (a count or an order), else a message naming the field;
	 * never converts an out-of-range double to an integer (undefined behaviour). */
	std::size_t count(const yaml& n, const std::string& key, const std::string& path, double lo, double hi) const
	{
		const double v = finite(n, key, path);
		if (v < lo || v > hi) fail(path + "." + key, num(v) + " is outside [" + num(lo) + ", " + num(hi) + "]");
		if (v != std::floor(v)) fail(path + "." + key, "expected a whole number");
		return static_cast<std::size_t>(v);
	}
	std::string text(const yaml& n, const std::string& key, const std::string& path) const
	{
		const yaml c = child(n, key, path);
		try
		{
			return c.isNullNode() ? std::string() : c.as<std::string>();
		}
		catch (const std::exception&)
		{
			fail(path + "." + key, "not a string");
		}
	}
	yaml::sequence_t seq(const yaml& n, const std::string& key, const std::string& path) const
	{
		const yaml c = child(n, key, path);
		if (!c.isSequence()) fail(path + "." + key, "expected a list");
		return c.asSequence();
	}
};

BiasModel readModel(const Reader& rd, const yaml& n, const std::string& path)
{
	BiasModel m;
	m.dropped = rd.text(n, "dropped", path);
	const auto terms = rd.seq(n, "terms", path);
	std::vector<std::string> names;
	std::vector<double> coefs;
	for (std::size_t i = 0; i < terms.size(); i++)
	{
		const std::string p = path + ".terms[" + std::to_string(i) + "]";
		const yaml t(terms[i]);
		names.push_back(rd.text(t, "name", p));
		coefs.push_back(rd.bounded(t, "coef_dph", p, -kMaxCoef_dph, kMaxCoef_dph, kCoefWhy));
	}
	if (names.empty() || names[0] != "1") rd.fail(path + ".terms", "the first term must be the constant \"1\"");
	try
	{
		m.features = ThermalFeatureSet::fromNames(names);
	}
	catch (const std::exception& e)
	{
		rd.fail(path + ".terms", e.what());
	}
	if (m.features.termCount() != coefs.size()) rd.fail(path + ".terms", "repeated constant term");
	m.coef_dph = coefs;
	const auto sigs = rd.seq(n, "signals", path);
	std::vector<bool> seen(m.features.signals().size(), false);
	for (std::size_t i = 0; i < sigs.size(); i++)
	{
		const std::string p = path + ".signals[" + std::to_string(i) + "]";
		const yaml s(sigs[i]);
		const std::string name = rd.text(s, "name", p);
		int idx = -1;
		for (std::size_t q = 0; q < m.features.signals().size(); q++)
			if (m.features.signals()[q].name() == name) idx = static_cast<int>(q);
		if (idx < 0) rd.fail(p + ".name", "signal '" + name + "' is used by no term");
		SignalNormalisation nm;
		// Plausible signal values: temperatures and their differences [degC], rates [degC/s],
		// hysteresis outputs [1] (in [-1, 1] by construction).
		const bool rate = m.features.signals()[idx].isRate() || m.features.signals()[idx].isLag();
		const bool hyst = m.features.signals()[idx].isHysteresis();
		const double lim = hyst ? 1.0 : rate ? kMaxSignalRate_Cps : kMaxSignal_C;
		const char* why = hyst ? "a hysteresis output lies in [-1, 1]"
						  : rate ? "a thermistor rate [degC/s] no coil reaches"
								 : "a temperature [degC] no coil reaches";
		nm.centre = rd.bounded(s, "centre", p, -lim, lim, why);
		nm.scale = rd.bounded(s, "scale", p, -lim, lim, why);
		nm.min = rd.bounded(s, "min", p, -lim, lim, why);
		nm.max = rd.bounded(s, "max", p, -lim, lim, why);
		if (!(nm.scale > 0)) rd.fail(p + ".scale", "must be > 0");
		if (nm.min > nm.max) rd.fail(p + ".min", "min > max");
		m.features.normalisation()[idx] = nm;
		seen[idx] = true;
	}
	for (std::size_t q = 0; q < seen.size(); q++)
		if (!seen[q]) rd.fail(path + ".signals", "no normalisation for signal '" + m.features.signals()[q].name() + "'");
	const std::size_t nt = m.features.termCount();
	m.covariance.setZero(static_cast<Eigen::Index>(nt), static_cast<Eigen::Index>(nt));
	const auto cov = rd.seq(n, "covariance_dph2", path);
	if (cov.size() != nt) rd.fail(path + ".covariance_dph2", "expected " + std::to_string(nt) + " rows");
	for (std::size_t r = 0; r < nt; r++)
	{
		const yaml row(cov[r]);
		if (!row.isSequence() || row.asSequence().size() != nt)
			rd.fail(path + ".covariance_dph2[" + std::to_string(r) + "]", "expected " + std::to_string(nt) + " numbers");
		for (std::size_t c = 0; c < nt; c++)
		{
			try
			{
				m.covariance(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
					std::stod(yaml(row.asSequence()[c]).as<std::string>());
			}
			catch (const std::exception&)
			{
				rd.fail(path + ".covariance_dph2[" + std::to_string(r) + "][" + std::to_string(c) + "]", "not a number");
			}
		}
	}
	const yaml fit = rd.child(n, "fit", path);
	const std::string fp = path + ".fit";
	m.samples = rd.count(fit, "samples", fp, 0, kMaxSamples);
	m.ridge = rd.finite(fit, "ridge", fp);
	m.condition_number = rd.number(fit, "condition_number", fp);
	m.numerical_rank = rd.count(fit, "numerical_rank", fp, 0, kMaxSamples);
	m.effective_dof = rd.finite(fit, "effective_dof", fp);
	m.rms_in_sample_dph = rd.number(fit, "rms_in_sample_dph", fp);
	m.rms_held_out_dph = rd.number(fit, "rms_held_out_dph", fp);
	return m;
}

FitFigures readFigures(const Reader& rd, const yaml& n, const std::string& path)
{
	FitFigures f;
	f.label = rd.text(n, "label", path);
	f.valid = rd.text(n, "valid", path) == "true";
	f.samples = rd.count(n, "samples", path, 0, kMaxSamples);
	f.tau_s = rd.number(n, "tau_s", path);
	f.rms_dph = rd.number(n, "rms_dph", path);
	f.stability_dph = rd.number(n, "stability_dph", path);
	f.range_dph = rd.number(n, "range_dph", path);
	f.raw_stability_dph = rd.number(n, "raw_stability_dph", path);
	f.raw_range_dph = rd.number(n, "raw_range_dph", path);
	return f;
}

/** A list of numbers (flow or block sequence) with "<path>[i]: not a number" errors. */
std::vector<double> readNumbers(const Reader& rd, const yaml& n, const std::string& key, const std::string& path)
{
	std::vector<double> v;
	const auto sq = rd.seq(n, key, path);
	for (std::size_t i = 0; i < sq.size(); i++)
	{
		try
		{
			const std::string t = yaml(sq[i]).as<std::string>();
			std::size_t used = 0;
			v.push_back(std::stod(t, &used));
			if (used != t.size()) throw std::invalid_argument("trailing text");
		}
		catch (const std::exception&)
		{
			rd.fail(path + "." + key + "[" + std::to_string(i) + "]", "not a number");
		}
		if (!std::isfinite(v.back())) rd.fail(path + "." + key + "[" + std::to_string(i) + "]", "must be a finite number");
	}
	return v;
}

Eigen::MatrixXd readSquare(const Reader& rd, const yaml& n, const std::string& key, const std::string& path, std::size_t size)
{
	Eigen::MatrixXd m(static_cast<Eigen::Index>(size), static_cast<Eigen::Index>(size));
	const auto rows = rd.seq(n, key, path);
	if (rows.size() != size) rd.fail(path + "." + key, "expected " + std::to_string(size) + " rows");
	for (std::size_t r = 0; r < size; r++)
	{
		const std::string p = path + "." + key + "[" + std::to_string(r) + "]";
		const yaml row(rows[r]);
		if (!row.isSequence() || row.asSequence().size() != size) rd.fail(p, "expected " + std::to_string(size) + " numbers");
		yaml holder = yaml::Map();
		holder["v"] = row;
		const std::vector<double> v = readNumbers(rd, holder, "v", p);
		for (std::size_t c = 0; c < size; c++) m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = v[c];
	}
	return m;
}

ScaleFactorModel readScaleFactor(const Reader& rd, const yaml& n, const std::string& path)
{
	ScaleFactorModel m;
	m.thermistor = rd.text(n, "thermistor", path);
	if (n.has("thermistors"))  // optional: the mean of these thermistors ("thermistor: mean")
	{
		for (const auto& t : rd.seq(n, "thermistors", path)) m.thermistors.push_back(yaml(t).as<std::string>());
		if (m.thermistors.empty()) rd.fail(path + ".thermistors", "must name at least one thermistor");
		const char* want = n.has("weights") ? "weighted" : "mean";
		if (m.thermistor != want)
			rd.fail(path + ".thermistor", std::string("must be \"") + want + "\" when thermistors is given" +
											  (n.has("weights") ? " with weights" : " without weights"));
	}
	if (n.has("weights"))  // optional: T = sum of weights x readings ("thermistor: weighted")
	{
		if (m.thermistors.empty()) rd.fail(path + ".weights", "needs thermistors: the readings they weight");
		m.weights = readNumbers(rd, n, "weights", path);
		if (m.weights.size() != m.thermistors.size())
			rd.fail(path + ".weights", std::to_string(m.weights.size()) + " weights for " +
										   std::to_string(m.thermistors.size()) + " thermistors");
		double sum = 0;
		for (std::size_t i = 0; i < m.weights.size(); i++)
		{
			if (!(std::abs(m.weights[i]) <= 100.0))
				rd.fail(path + ".weights[" + std::to_string(i) + "]",
						num(m.weights[i]) + " is outside [-100, 100] (a weight of a thermistor reading)");
			sum += m.weights[i];
		}
		if (!(std::abs(sum - 1.0) <= 1e-6)) rd.fail(path + ".weights", "sum to " + num(sum) + ", must sum to 1");
	}
	const char* why = "a temperature [degC] no coil reaches";
	m.centre_C = rd.bounded(n, "centre_C", path, -kMaxSignal_C, kMaxSignal_C, why);
	m.scale_C = rd.bounded(n, "scale_C", path, -kMaxSignal_C, kMaxSignal_C, why);
	m.min_C = rd.bounded(n, "min_C", path, -kMaxSignal_C, kMaxSignal_C, why);
	m.max_C = rd.bounded(n, "max_C", path, -kMaxSignal_C, kMaxSignal_C, why);
	if (!(m.scale_C > 0)) rd.fail(path + ".scale_C", "must be > 0");
	if (m.min_C > m.max_C) rd.fail(path + ".min_C", "min_C > max_C");
	m.coef_ppm = readNumbers(rd, n, "coef_ppm", path);
	if (m.coef_ppm.empty() || m.coef_ppm.size() > 6) rd.fail(path + ".coef_ppm", "expected 1 to 6 coefficients");
	for (std::size_t k = 0; k < m.coef_ppm.size(); k++)
		if (std::abs(m.coef_ppm[k]) > kMaxCoef_ppm)
			rd.fail(path + ".coef_ppm[" + std::to_string(k) + "]", num(m.coef_ppm[k]) + " is outside [-1e5, 1e5] (" + kPpmWhy + ")");
	m.covariance_ppm2 = readSquare(rd, n, "covariance_ppm2", path, m.coef_ppm.size());
	m.slope_ppm_per_C = rd.number(n, "slope_ppm_per_C", path);
	const auto ci = readNumbers(rd, n, "slope_ci95_ppm_per_C", path);
	if (ci.size() != 2) rd.fail(path + ".slope_ci95_ppm_per_C", "expected [lo, hi]");
	m.slope_ci95_lo_ppm_per_C = ci[0];
	m.slope_ci95_hi_ppm_per_C = ci[1];
	if (n.has("slope_thermistors"))  // written since the interval covers the temperature errors
	{
		const auto nc = readNumbers(rd, n, "slope_noise_ci95_ppm_per_C", path);
		if (nc.size() != 2) rd.fail(path + ".slope_noise_ci95_ppm_per_C", "expected [lo, hi]");
		const auto rg = readNumbers(rd, n, "slope_thermistor_range_ppm_per_C", path);
		if (rg.size() != 2) rd.fail(path + ".slope_thermistor_range_ppm_per_C", "expected [min, max]");
		m.slope_noise_ci95_lo_ppm_per_C = nc[0];
		m.slope_noise_ci95_hi_ppm_per_C = nc[1];
		m.slope_thermistor_min_ppm_per_C = rg[0];
		m.slope_thermistor_max_ppm_per_C = rg[1];
		m.slope_thermistors = rd.count(n, "slope_thermistors", path, 1, 64);
	}
	const auto tr = readNumbers(rd, n, "table_rate_abs_dph", path);
	if (tr.size() != 2) rd.fail(path + ".table_rate_abs_dph", "expected [min, max]");
	m.table_rate_min_abs_dph = tr[0];
	m.table_rate_max_abs_dph = tr[1];
	m.segments = rd.count(n, "segments", path, 0, kMaxSamples);
	m.samples = rd.count(n, "samples", path, 0, kMaxSamples);
	m.rms_in_sample_ppm = rd.number(n, "rms_in_sample_ppm", path);
	m.rms_held_out_ppm = rd.number(n, "rms_held_out_ppm", path);
	m.held_out_label = rd.text(n, "held_out_label", path);
	return m;
}

MagneticModel readMagnetic(const Reader& rd, const yaml& n, const std::string& path)
{
	MagneticModel m;
	m.dph_per_uT = rd.bounded(n, "dph_per_uT", path, -kMaxCoef_dph, kMaxCoef_dph, kCoefWhy);
	m.dph_per_uT_std = rd.finite(n, "dph_per_uT_std", path);
	if (!(m.dph_per_uT_std >= 0)) rd.fail(path + ".dph_per_uT_std", "must be >= 0");
	const auto range = readNumbers(rd, n, "field_range_uT", path);
	if (range.size() != 2) rd.fail(path + ".field_range_uT", "expected [min, max]");
	if (!std::isfinite(range[0]) || !std::isfinite(range[1]))
		rd.fail(path + ".field_range_uT", "must be finite numbers");
	if (range[0] > range[1]) rd.fail(path + ".field_range_uT", "min > max");
	if (std::abs(range[0]) > units::kMaxAbsField_uT || std::abs(range[1]) > units::kMaxAbsField_uT)
		rd.fail(path + ".field_range_uT", "beyond the plausible field of " + num(units::kMaxAbsField_uT) + " uT");
	// the term's contribution, not only its coefficient: up to the largest field a log may hold
	if (std::abs(m.dph_per_uT) * units::kMaxAbsField_uT > kMaxCoef_dph)
		rd.fail(path + ".dph_per_uT", num(m.dph_per_uT) + " deg/h per uT gives a term of " +
										  num(std::abs(m.dph_per_uT) * units::kMaxAbsField_uT) + " deg/h at " +
										  num(units::kMaxAbsField_uT) + " uT: " + kCoefWhy);
	m.field_min_uT = range[0];
	m.field_max_uT = range[1];
	m.samples = rd.count(n, "samples", path, 0, kMaxSamples);
	return m;
}

WarmupModel readWarmup(const Reader& rd, const yaml& n, const std::string& path)
{
	WarmupModel w;
	w.amplitude_dph = rd.bounded(n, "amplitude_dph", path, -kMaxCoef_dph, kMaxCoef_dph, kCoefWhy);
	w.tau_s = rd.bounded(n, "tau_s", path, -kMaxWarmupTau_s, kMaxWarmupTau_s, "a warm-up of more than 10 days is none");
	if (!(w.tau_s > 0)) rd.fail(path + ".tau_s", "must be > 0");
	w.amplitude_std_dph = rd.number(n, "amplitude_std_dph", path);
	w.tau_std_s = rd.number(n, "tau_std_s", path);
	w.fitted_span_s = rd.number(n, "fitted_span_s", path);
	w.turn_ons = rd.count(n, "turn_ons", path, 0, kMaxSamples);
	w.samples = rd.count(n, "samples", path, 0, kMaxSamples);
	w.rms_before_dph = rd.number(n, "rms_before_dph", path);
	w.rms_after_dph = rd.number(n, "rms_after_dph", path);
	if (n.has("amplitude2_dph"))  // optional: a second exponential term
	{
		w.amplitude2_dph = rd.bounded(n, "amplitude2_dph", path, -kMaxCoef_dph, kMaxCoef_dph, kCoefWhy);
		w.tau2_s = rd.bounded(n, "tau2_s", path, -kMaxWarmupTau_s, kMaxWarmupTau_s, "a warm-up of more than 10 days is none");
		if (!(w.tau2_s > 0)) rd.fail(path + ".tau2_s", "must be > 0");
		w.amplitude2_std_dph = rd.number(n, "amplitude2_std_dph", path);
		w.tau2_std_s = rd.number(n, "tau2_std_s", path);
	}
	if (n.has("startup_offset_dph"))  // optional (files before session 7 have none: 0)
	{
		w.startup_offset_dph = rd.bounded(n, "startup_offset_dph", path, -kMaxCoef_dph, kMaxCoef_dph, kCoefWhy);
		w.startup_offset_std_dph = rd.number(n, "startup_offset_std_dph", path);
		w.startup_samples = rd.count(n, "startup_samples", path, 0, kMaxSamples);
	}
	return w;
}
}  // namespace

namespace
{
void writeAxis(std::ostringstream& o, const Calibration& cal)
{
	const std::string ind = "    ";
	o << "  - axis: \"" << axisLetter(cal.axis) << "\"\n";
	o << ind << "preset: " << str(cal.preset) << "\n";
	o << ind << "selection: " << str(toString(cal.selection)) << "\n";
	o << ind << "rate_estimator:\n";
	o << ind << "  kind: " << str(toString(cal.rate_estimator.kind)) << "\n";
	o << ind << "  window_s: " << num(cal.rate_estimator.window_s) << "\n";
	o << ind << "  poly_order: " << cal.rate_estimator.poly_order << "\n";
	o << ind << "  delay_s: " << num(cal.rate_estimator.kind == RateEstimatorKind::Causal && cal.rate_estimator.poly_order == 1 ? cal.rate_estimator.window_s / 2 : 0.0)
	  << (cal.rate_estimator.kind == RateEstimatorKind::Causal && cal.rate_estimator.poly_order == 2
			  ? "  # informational: order 2 extrapolates the slope to the newest sample (no delay)\n"
			  : "  # informational: the causal estimate lags by about window_s / 2\n");
	o << ind << "calibration_runs: [";
	for (std::size_t i = 0; i < cal.runs.size(); i++) o << (i ? ", " : "") << str(cal.runs[i]);
	o << "]\n";
	o << ind << "bias:  # bias_dph = sum coef_dph * z^k; compensated = raw - bias\n";
	o << ind << "  mean_bias_dph: " << num(cal.mean_bias_dph)
	  << "  # used when no model applies (>= 2 thermistors missing)\n";
	o << ind << "  extrapolation: " << str(toString(cal.extrapolation))
	  << "  # outside the calibrated range: linear | clamp | polynomial\n";
	if (readsLags(cal))
		o << ind << "  lag_filter: " << str(kLagFilter)
		  << "  # dTlag/dt(a,tau) = (T(a) - y) / tau, dy/dt = (T(a) - y) / tau integrated exactly for readings linear between samples; y = the first valid reading at start (LagFilter.h)\n";
	if (readsHysteresis(cal))
		o << ind << "  hysteresis_filter: " << str(hysteresisFilterText())
		  << "  # hyst(a,play,w): p <- min(max(p, T - w), T + w), h = (T - p) / w; hyst(a,branch,w): h <- s + (h - s) exp(-|dq| / w), s = sign(dq), q a play of half-width the dead band; p, q = the first valid reading and h = 0 at start (HysteresisFilter.h)\n";
	o << ind << "  model:\n";
	writeModel(o, cal.model, ind + "    ");
	o << ind << "  fallbacks:" << (cal.fallbacks.empty() ? " []" : "") << "\n";
	for (const auto& f : cal.fallbacks)
	{
		std::ostringstream m;
		writeModel(m, f, ind + "    ");
		std::string s = m.str();
		s.replace(ind.size() + 2, 2, "- ");
		o << s;
	}
	if (cal.startup)  // optional: used until the rates the main model reads are estimable
	{
		o << ind << "  startup_model:  # rate-free: used while the main model's rate windows cover < half their length\n";
		writeModel(o, *cal.startup, ind + "    ");
	}
	if (cal.selection_stability.resamples > 0)  // optional: how stable the term choice is
	{
		const auto& st = cal.selection_stability;
		o << ind << "  selection_stability:  # refits on wild-bootstrap resamples of the calibration data\n";
		o << ind << "    resamples: " << st.resamples << "\n";
		o << ind << "    chosen_share: " << num(st.chosen_share) << "  # share of refits that chose this model\n";
		o << ind << "    stable: " << (st.stable ? "true" : "false") << "\n";
		o << ind << "    alternatives:" << (st.alternatives.empty() ? " []" : "") << "\n";
		for (const auto& a : st.alternatives)
			o << ind << "      - {terms: " << str(a.terms) << ", share: " << num(a.share)
			  << ", held_out_rms_dph: " << num(a.held_out_rms_dph) << "}\n";
	}
	if (cal.scale_factor) writeScaleFactor(o, *cal.scale_factor, ind);
	if (cal.warmup) writeWarmup(o, *cal.warmup, ind);
	if (cal.magnetic) writeMagnetic(o, *cal.magnetic, ind);
	o << ind << "statistics:  # of the bias compensation\n";
	writeFigures(o, "in_sample", cal.in_sample, ind + "  ");
	writeFigures(o, "held_out", cal.held_out, ind + "  ");
	writeFigures(o, "validation", cal.validation, ind + "  ");
}
}  // namespace

std::string calibrationSetToYaml(const CalibrationSet& set)
{
	set.validate();
	const Calibration& a = set.axes.front();
	std::ostringstream o;
	o << "# mrpt_fog calibration (fog-calibrate): per gyro axis a thermal bias model, optionally a\n";
	o << "# scale factor vs temperature and a warm-up term. Units: temperatures degC, rates degC/s,\n";
	bool extended = false;
	for (const auto& c : set.axes) extended |= readsLags(c) || readsHysteresis(c) || c.magnetic.has_value();
	const int version = extended ? kVersionExtended : kVersion;
	o << "# bias deg/h, scale factor ppm. Layout: docs/reference/model.md (calibration file, version " << version << ").\n";
	o << "format: " << str(kFormat) << "\n";
	o << "version: " << version << "\n";
	o << "sensor:\n";
	o << "  label: " << str(a.sensor_label) << "\n";
	o << "  thermistors:" << (a.layout.empty() ? " []" : "") << "\n";
	for (const auto& t : a.layout)
		o << "    - name: " << str(t.name) << "\n      side: " << str(toString(t.side))
		  << "\n      angle_deg: " << num(t.angle_deg) << "\n";
	o << "latitude_deg: " << num(a.latitude_deg) << "  # of the calibration runs [deg]; .nan = unknown\n";
	o << "earth_rate:\n";
	o << "  handling: " << str(toString(a.earth_rate))
	  << "  # in_bias: the bias holds the axis' Earth-rate projection at latitude_deg; in_table_rate: it does not\n";
	o << "axes:\n";
	for (const auto& c : set.axes) writeAxis(o, c);
	return o.str();
}

std::string calibrationToYaml(const Calibration& cal)
{
	return calibrationSetToYaml(CalibrationSet{{cal}});
}

namespace
{
void readLayout(const Reader& rd, const yaml& sensor, Calibration& cal)
{
	cal.sensor_label = rd.text(sensor, "label", "sensor");
	const auto therm = rd.seq(sensor, "thermistors", "sensor");
	for (std::size_t i = 0; i < therm.size(); i++)
	{
		const std::string p = "sensor.thermistors[" + std::to_string(i) + "]";
		const yaml t(therm[i]);
		ThermistorInfo info;
		info.name = rd.text(t, "name", p);
		if (!isValidThermistorName(info.name)) rd.fail(p + ".name", "invalid thermistor name '" + info.name + "'");
		for (const auto& o : cal.layout)
			if (o.name == info.name) rd.fail(p + ".name", "thermistor '" + info.name + "' listed twice");
		try
		{
			info.side = coilSideFromString(rd.text(t, "side", p));
		}
		catch (const std::invalid_argument& e)
		{
			rd.fail(p + ".side", e.what());
		}
		info.angle_deg = rd.finite(t, "angle_deg", p);
		cal.layout.push_back(info);
	}
}

GyroAxis readAxisLetter(const Reader& rd, const yaml& n, const std::string& path)
{
	const std::string axis = rd.text(n, "axis", path);
	if (axis != "x" && axis != "y" && axis != "z") rd.fail((path.empty() ? "" : path + ".") + "axis", "must be x, y or z");
	return static_cast<GyroAxis>(axis[0] - 'x');
}

/** The per-axis fields: `n` holds preset, selection, rate_estimator and calibration_runs;
 * `bias` holds mean_bias_dph, model and fallbacks; `stats` the statistics (version 1: all three
 * are the top level). Paths in errors are prefixed with `p` / `bp`. */
void readAxisFields(const Reader& rd, const yaml& n, const std::string& p, const yaml& bias, const std::string& bp,
					const yaml& stats, const std::string& sp, Calibration& cal)
{
	const auto at = [](const std::string& base, const std::string& key) { return base.empty() ? key : base + "." + key; };
	cal.preset = rd.text(n, "preset", p);
	const std::string selection = rd.text(n, "selection", p);
	try
	{
		cal.selection = termSelectionFromString(selection);
	}
	catch (const std::invalid_argument& e)
	{
		rd.fail(at(p, "selection"), e.what());
	}
	const yaml est = rd.child(n, "rate_estimator", p);
	const std::string ep = at(p, "rate_estimator");
	const std::string kind = rd.text(est, "kind", ep);
	cal.rate_estimator.window_s = rd.finite(est, "window_s", ep);
	cal.rate_estimator.poly_order = static_cast<int>(rd.count(est, "poly_order", ep, 0, 64));
	try
	{
		cal.rate_estimator.kind = rateEstimatorKindFromString(kind);
		cal.rate_estimator.validate();
	}
	catch (const std::invalid_argument& e)
	{
		rd.fail(ep, e.what());
	}
	cal.mean_bias_dph = rd.bounded(bias, "mean_bias_dph", bp, -kMaxCoef_dph, kMaxCoef_dph, kCoefWhy);
	// Extrapolation policy: in the bias section (version 2) or at the top (version 1
	// files written after it was added); a version 1 file without it was made for clamping.
	if (bias.has("extrapolation"))
	{
		try
		{
			cal.extrapolation = extrapolationPolicyFromString(rd.text(bias, "extrapolation", bp));
		}
		catch (const std::invalid_argument& e)
		{
			rd.fail(at(bp, "extrapolation"), e.what());
		}
	}
	else if (bp.empty())
		cal.extrapolation = ExtrapolationPolicy::Clamp;
	for (const auto& r : rd.seq(n, "calibration_runs", p)) cal.runs.push_back(yaml(r).as<std::string>());
	const auto checkLayout = [&](const BiasModel& m, const std::string& path) {
		for (const auto& name : m.features.thermistors())
		{
			bool found = false;
			for (const auto& t : cal.layout) found |= t.name == name;
			if (!found) rd.fail(path, "uses thermistor '" + name + "', which is not in sensor.thermistors");
		}
	};
	const std::string mp = at(bp, "model");
	cal.model = readModel(rd, rd.child(bias, "model", bp), mp);
	checkLayout(cal.model, mp);
	if (!cal.model.dropped.empty()) rd.fail(mp + ".dropped", "must be empty for the main model");
	const auto fbs = rd.seq(bias, "fallbacks", bp);
	for (std::size_t i = 0; i < fbs.size(); i++)
	{
		const std::string fp = at(bp, "fallbacks[" + std::to_string(i) + "]");
		BiasModel m = readModel(rd, yaml(fbs[i]), fp);
		checkLayout(m, fp);
		if (m.dropped.empty() || !cal.model.features.references(m.dropped))
			rd.fail(fp + ".dropped", "must name a thermistor of the main model");
		if (m.features.references(m.dropped)) rd.fail(fp, "uses its own dropped thermistor '" + m.dropped + "'");
		cal.fallbacks.push_back(std::move(m));
	}
	if (bias.has("startup_model"))  // optional: the rate-free start-up model
	{
		const std::string up = at(bp, "startup_model");
		BiasModel m = readModel(rd, rd.child(bias, "startup_model", bp), up);
		checkLayout(m, up);
		if (!m.dropped.empty()) rd.fail(up + ".dropped", "must be empty for the start-up model");
		for (const auto& sig : m.features.signals())
			if (sig.kind == SignalKind::Rate || sig.kind == SignalKind::DiffRate)
				rd.fail(up, "reads the rate signal " + sig.name() + ": the start-up model must be rate-free");
		for (const auto& name : m.features.thermistors())
			if (!cal.model.features.references(name))
				rd.fail(up, "uses thermistor '" + name + "', which the main model does not read");
		cal.startup = std::move(m);
	}
	if (bias.has("selection_stability"))  // optional
	{
		const std::string ssp = at(bp, "selection_stability");
		const yaml ss = rd.child(bias, "selection_stability", bp);
		auto& st = cal.selection_stability;
		st.resamples = rd.count(ss, "resamples", ssp, 0, 1e6);
		st.chosen_share = rd.bounded(ss, "chosen_share", ssp, 0, 1, "a share");
		const std::string stable = rd.text(ss, "stable", ssp);
		if (stable != "true" && stable != "false") rd.fail(ssp + ".stable", "must be true or false");
		st.stable = stable == "true";
		const auto alts = rd.seq(ss, "alternatives", ssp);
		for (std::size_t i = 0; i < alts.size(); i++)
		{
			const std::string ap = ssp + ".alternatives[" + std::to_string(i) + "]";
			const yaml a(alts[i]);
			SelectionStability::Alternative alt;
			alt.terms = rd.text(a, "terms", ap);
			alt.share = rd.bounded(a, "share", ap, 0, 1, "a share");
			alt.held_out_rms_dph = rd.bounded(a, "held_out_rms_dph", ap, 0, kMaxCoef_dph, kCoefWhy);
			st.alternatives.push_back(alt);
		}
	}
	const std::string stp = at(sp, "statistics");
	const yaml st = rd.child(stats, "statistics", sp);
	cal.in_sample = readFigures(rd, rd.child(st, "in_sample", stp), stp + ".in_sample");
	cal.held_out = readFigures(rd, rd.child(st, "held_out", stp), stp + ".held_out");
	cal.validation = readFigures(rd, rd.child(st, "validation", stp), stp + ".validation");
}

CalibrationSet parseCalibrationYaml(const std::string& text, const std::string& source)
{
	Reader rd{source};
	requireSafeYamlText(text, source);  // size, nesting depth, aliases, UTF-8: before MRPT's parser
	yaml root;
	try
	{
		root = yaml::FromText(text);
	}
	catch (const std::exception& e)
	{
		throw std::invalid_argument(source + ": not valid YAML: " + oneLineErrorMessage(e.what()));
	}
	if (!root.isMap()) rd.fail("(top)", "expected a YAML map");
	if (rd.text(root, "format", "") != kFormat) rd.fail("format", std::string("expected ") + kFormat);
	const double version = rd.finite(root, "version", "");
	if (version != 1 && version != kVersion && version != kVersionExtended)
		rd.fail("version", "unsupported version " + num(version) + " (this build reads 1, 2 and 3)");
	const yaml sensor = rd.child(root, "sensor", "");
	Calibration common;
	readLayout(rd, sensor, common);
	CalibrationSet set;
	if (version == 1)
	{
		// Single axis, bias only, latitude unknown: the bias holds whatever Earth rate the runs saw.
		Calibration cal = common;
		cal.axis = readAxisLetter(rd, sensor, "sensor");
		readAxisFields(rd, root, "", root, "", root, "", cal);
		if (readsLags(cal)) rd.fail("model", "reads lag signals (dTlag/dt), which need file version 3 (the file says 1)");
		if (root.has("magnetic"))
			rd.fail("magnetic", "a magnetic-sensitivity section needs file version 3 (the file says 1)");
		if (readsHysteresis(cal))
			rd.fail("model", "reads hysteresis signals (hyst), which need file version 3 (the file says 1)");
		set.axes.push_back(std::move(cal));
		return set;
	}
	common.latitude_deg = rd.number(root, "latitude_deg", "");
	if (!std::isnan(common.latitude_deg) && !(std::abs(common.latitude_deg) <= 90))
		rd.fail("latitude_deg", "must be within [-90, 90] or .nan (unknown)");
	try
	{
		common.earth_rate = earthRateHandlingFromString(rd.text(rd.child(root, "earth_rate", ""), "handling", "earth_rate"));
	}
	catch (const std::invalid_argument& e)
	{
		if (std::string(e.what()).rfind(source, 0) == 0) throw;
		rd.fail("earth_rate.handling", e.what());
	}
	const auto axes = rd.seq(root, "axes", "");
	if (axes.empty() || axes.size() > 3) rd.fail("axes", "expected 1 to 3 axis entries");
	for (std::size_t i = 0; i < axes.size(); i++)
	{
		const std::string p = "axes[" + std::to_string(i) + "]";
		const yaml a(axes[i]);
		Calibration cal = common;
		cal.axis = readAxisLetter(rd, a, p);
		for (const auto& other : set.axes)
			if (other.axis == cal.axis) rd.fail(p + ".axis", std::string("axis ") + axisLetter(cal.axis) + " is listed twice");
		readAxisFields(rd, a, p, rd.child(a, "bias", p), p + ".bias", a, p, cal);
		if (readsLags(cal))
		{
			if (version < kVersionExtended)
				rd.fail(p + ".bias", "reads lag signals (dTlag/dt), which need file version 3 (the file says " + num(version) + ")");
			if (rd.text(rd.child(a, "bias", p), "lag_filter", p + ".bias") != kLagFilter)
				rd.fail(p + ".bias.lag_filter", std::string("expected \"") + kLagFilter + "\" (the only lag this build runs)");
		}
		if (readsHysteresis(cal))
		{
			if (version < kVersionExtended)
				rd.fail(p + ".bias", "reads hysteresis signals (hyst), which need file version 3 (the file says " +
										 num(version) + ")");
			if (rd.text(rd.child(a, "bias", p), "hysteresis_filter", p + ".bias") != hysteresisFilterText())
				rd.fail(p + ".bias.hysteresis_filter",
						"expected \"" + hysteresisFilterText() + "\" (the only hysteresis operators this build runs)");
		}
		if (a.has("scale_factor"))
		{
			cal.scale_factor = readScaleFactor(rd, a["scale_factor"], p + ".scale_factor");
			bool found = false;
			for (const auto& t : cal.layout) found |= t.name == cal.scale_factor->thermistor;
			for (const auto& name : cal.scale_factor->thermistors)
			{
				bool listed = false;
				for (const auto& t : cal.layout) listed |= t.name == name;
				if (!listed) rd.fail(p + ".scale_factor.thermistors", "'" + name + "' is not in sensor.thermistors");
			}
			if (!cal.scale_factor->thermistors.empty()) found = true;
			if (!found)
				rd.fail(p + ".scale_factor.thermistor",
						"'" + cal.scale_factor->thermistor + "' is not in sensor.thermistors");
		}
		if (a.has("warmup")) cal.warmup = readWarmup(rd, a["warmup"], p + ".warmup");
		if (a.has("magnetic"))
		{
			if (version < kVersionExtended)
				rd.fail(p + ".magnetic", "a magnetic-sensitivity section needs file version 3 (the file says " +
											 num(version) + "): a version-2 reader would ignore it");
			cal.magnetic = readMagnetic(rd, a["magnetic"], p + ".magnetic");
		}
		set.axes.push_back(std::move(cal));
	}
	return set;
}

template <typename F>
auto withFieldErrors(const std::string& source, F&& f) -> decltype(f())
{
	try
	{
		return f();
	}
	catch (const std::invalid_argument&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		// MRPT's YAML accessors throw std::logic_error for a node of the wrong kind (e.g. a map
		// where a scalar is expected; found by fuzz_calibration_yaml): same contract as our own
		// field errors.
		throw std::invalid_argument(source + ": " + oneLineErrorMessage(e.what()));
	}
}

std::string axesText(const CalibrationSet& set)
{
	std::string s;
	for (const auto& c : set.axes) s += (s.empty() ? "" : ", ") + std::string(1, axisLetter(c.axis));
	return s;
}

std::string readWholeFile(const std::string& path)
{
	return readYamlTextLimited(path);
}
}  // namespace

CalibrationSet calibrationSetFromYaml(const std::string& text, const std::string& source)
{
	return withFieldErrors(source, [&] { return parseCalibrationYaml(text, source); });
}

Calibration calibrationFromYaml(const std::string& text, const std::string& source)
{
	CalibrationSet set = calibrationSetFromYaml(text, source);
	if (set.axes.size() != 1)
		throw std::invalid_argument(source + ": axes: holds " + std::to_string(set.axes.size()) + " axes (" +
									axesText(set) + "); choose one");
	return std::move(set.axes.front());
}

Calibration calibrationFromYaml(const std::string& text, const std::string& source, GyroAxis axis)
{
	CalibrationSet set = calibrationSetFromYaml(text, source);
	for (auto& c : set.axes)
		if (c.axis == axis) return std::move(c);
	throw std::invalid_argument(source + ": axes: no calibration for axis " + std::string(1, axisLetter(axis)) +
								" (the file has " + axesText(set) + ")");
}

void saveCalibrationYaml(const Calibration& cal, const std::string& path)
{
	writeTextFileAtomically(path, calibrationToYaml(cal));
}

void saveCalibrationSet(const CalibrationSet& set, const std::string& path)
{
	writeTextFileAtomically(path, calibrationSetToYaml(set));
}

Calibration loadCalibrationYaml(const std::string& path)
{
	return calibrationFromYaml(readWholeFile(path), path);
}

Calibration loadCalibrationYaml(const std::string& path, GyroAxis axis)
{
	return calibrationFromYaml(readWholeFile(path), path, axis);
}

CalibrationSet loadCalibrationSet(const std::string& path)
{
	return calibrationSetFromYaml(readWholeFile(path), path);
}

}  // namespace mrpt_fog
