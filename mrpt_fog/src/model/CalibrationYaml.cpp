/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/containers/yaml.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/ErrorText.h>
#include <mrpt_fog/common/Utf8.h>
#include <mrpt_fog/common/YamlGuard.h>
#include <mrpt_fog/model/CalibrationYaml.h>

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
constexpr int kVersion = 1;
// Plausibility limits of loaded values (issue 14: a coef_dph of 1e308 compensated to -2e307
// deg/h). Every term is z^k with |z| <= 1 after clamping, so a coefficient bounds its term's
// contribution to the bias: 1e6 deg/h (278 deg/s) is beyond any gyro's bias.
constexpr double kMaxCoef_dph = 1e6;
constexpr const char* kCoefWhy = "a bias term of more than 1e6 deg/h is no gyro's";
constexpr double kMaxSignal_C = 1000.0;  // temperatures and differences [degC]
constexpr double kMaxSignalRate_Cps = 100.0;  // temperature rates [degC/s]

std::string num(double v)
{
	if (std::isnan(v)) return ".nan";
	if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
	char buf[40];
	std::snprintf(buf, sizeof(buf), "%.17g", v);
	return buf;
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

void writeFigures(std::ostringstream& o, const std::string& key, const FitFigures& f)
{
	o << "  " << key << ":\n";
	o << "    label: " << str(f.label) << "\n";
	o << "    valid: " << (f.valid ? "true" : "false") << "\n";
	o << "    samples: " << f.samples << "\n";
	o << "    tau_s: " << num(f.tau_s) << "\n";
	o << "    rms_dph: " << num(f.rms_dph) << "  # compensated, about its mean [deg/h]\n";
	o << "    stability_dph: " << num(f.stability_dph) << "  # std of tau-s averages, compensated [deg/h]\n";
	o << "    range_dph: " << num(f.range_dph) << "  # max - min of tau-s averages, compensated [deg/h]\n";
	o << "    raw_stability_dph: " << num(f.raw_stability_dph) << "\n";
	o << "    raw_range_dph: " << num(f.raw_range_dph) << "\n";
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
	for (Eigen::Index r = 0; r < m.covariance.rows(); r++)
	{
		o << ind << "  - [";
		for (Eigen::Index c = 0; c < m.covariance.cols(); c++) o << (c ? ", " : "") << num(m.covariance(r, c));
		o << "]\n";
	}
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
		// Plausible signal values: temperatures and their differences [degC], rates [degC/s].
		const bool rate = m.features.signals()[idx].isRate();
		const double lim = rate ? kMaxSignalRate_Cps : kMaxSignal_C;
		const char* why = rate ? "a thermistor rate [degC/s] no coil reaches" : "a temperature [degC] no coil reaches";
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
	m.samples = static_cast<std::size_t>(rd.finite(fit, "samples", fp));
	m.ridge = rd.finite(fit, "ridge", fp);
	m.condition_number = rd.number(fit, "condition_number", fp);
	m.numerical_rank = static_cast<std::size_t>(rd.finite(fit, "numerical_rank", fp));
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
	f.samples = static_cast<std::size_t>(rd.finite(n, "samples", path));
	f.tau_s = rd.number(n, "tau_s", path);
	f.rms_dph = rd.number(n, "rms_dph", path);
	f.stability_dph = rd.number(n, "stability_dph", path);
	f.range_dph = rd.number(n, "range_dph", path);
	f.raw_stability_dph = rd.number(n, "raw_stability_dph", path);
	f.raw_range_dph = rd.number(n, "raw_range_dph", path);
	return f;
}
}  // namespace

std::string calibrationToYaml(const Calibration& cal)
{
	std::ostringstream o;
	o << "# mrpt_fog thermal-bias calibration (fog-calibrate). bias_dph = sum coef_dph * z^k;\n";
	o << "# compensated rate = raw rate - bias. Units: temperatures degC, rates degC/s, bias deg/h.\n";
	o << "format: " << str(kFormat) << "\n";
	o << "version: " << kVersion << "\n";
	o << "sensor:\n";
	o << "  label: " << str(cal.sensor_label) << "\n";
	o << "  axis: \"" << axisLetter(cal.axis) << "\"\n";
	o << "  thermistors:\n";
	for (const auto& t : cal.layout)
		o << "    - name: " << str(t.name) << "\n      side: " << str(toString(t.side))
		  << "\n      angle_deg: " << num(t.angle_deg) << "\n";
	o << "preset: " << str(cal.preset) << "\n";
	o << "selection: " << str(cal.selection) << "\n";
	o << "extrapolation: " << str(toString(cal.extrapolation)) << "  # outside the calibrated range: linear | clamp | polynomial\n";
	o << "rate_estimator:\n";
	o << "  kind: " << str(cal.rate_estimator.kind) << "\n";
	o << "  window_s: " << num(cal.rate_estimator.window_s) << "\n";
	o << "  poly_order: " << cal.rate_estimator.poly_order << "\n";
	o << "  delay_s: " << num(cal.rate_estimator.kind == "causal" ? cal.rate_estimator.window_s / 2 : 0.0)
	  << "  # informational: the causal estimate lags by about window_s / 2\n";
	o << "mean_bias_dph: " << num(cal.mean_bias_dph) << "  # used when no model applies (>= 2 thermistors missing)\n";
	o << "calibration_runs: [";
	for (std::size_t i = 0; i < cal.runs.size(); i++) o << (i ? ", " : "") << str(cal.runs[i]);
	o << "]\n";
	o << "model:\n";
	writeModel(o, cal.model, "  ");
	o << "fallbacks:";
	if (cal.fallbacks.empty()) o << " []";
	o << "\n";
	for (const auto& f : cal.fallbacks)
	{
		std::ostringstream m;
		writeModel(m, f, "    ");
		std::string s = m.str();
		s.replace(0, 4, "  - ");
		o << s;
	}
	o << "statistics:\n";
	writeFigures(o, "in_sample", cal.in_sample);
	writeFigures(o, "held_out", cal.held_out);
	writeFigures(o, "validation", cal.validation);
	return o.str();
}

namespace
{
Calibration parseCalibrationYaml(const std::string& text, const std::string& source)
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
	if (version != kVersion) rd.fail("version", "unsupported version " + num(version));
	Calibration cal;
	const yaml sensor = rd.child(root, "sensor", "");
	cal.sensor_label = rd.text(sensor, "label", "sensor");
	const std::string axis = rd.text(sensor, "axis", "sensor");
	if (axis != "x" && axis != "y" && axis != "z") rd.fail("sensor.axis", "must be x, y or z");
	cal.axis = static_cast<GyroAxis>(axis[0] - 'x');
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
	cal.preset = rd.text(root, "preset", "");
	cal.selection = rd.text(root, "selection", "");
	if (root.has("extrapolation"))  // optional (issue 11); absent: the default, linear
	{
		try
		{
			cal.extrapolation = extrapolationPolicyFromString(rd.text(root, "extrapolation", ""));
		}
		catch (const std::invalid_argument& e)
		{
			rd.fail("extrapolation", e.what());
		}
	}
	const yaml est = rd.child(root, "rate_estimator", "");
	cal.rate_estimator.kind = rd.text(est, "kind", "rate_estimator");
	cal.rate_estimator.window_s = rd.finite(est, "window_s", "rate_estimator");
	cal.rate_estimator.poly_order = static_cast<int>(rd.finite(est, "poly_order", "rate_estimator"));
	try
	{
		cal.rate_estimator.validate();
	}
	catch (const std::invalid_argument& e)
	{
		rd.fail("rate_estimator", e.what());
	}
	cal.mean_bias_dph = rd.bounded(root, "mean_bias_dph", "", -kMaxCoef_dph, kMaxCoef_dph, kCoefWhy);
	for (const auto& r : rd.seq(root, "calibration_runs", "")) cal.runs.push_back(yaml(r).as<std::string>());
	const auto checkLayout = [&](const BiasModel& m, const std::string& path) {
		for (const auto& n : m.features.thermistors())
		{
			bool found = false;
			for (const auto& t : cal.layout) found |= t.name == n;
			if (!found) rd.fail(path, "uses thermistor '" + n + "', which is not in sensor.thermistors");
		}
	};
	cal.model = readModel(rd, rd.child(root, "model", ""), "model");
	checkLayout(cal.model, "model");
	if (!cal.model.dropped.empty()) rd.fail("model.dropped", "must be empty for the main model");
	const auto fbs = rd.seq(root, "fallbacks", "");
	for (std::size_t i = 0; i < fbs.size(); i++)
	{
		const std::string p = "fallbacks[" + std::to_string(i) + "]";
		BiasModel m = readModel(rd, yaml(fbs[i]), p);
		checkLayout(m, p);
		if (m.dropped.empty() || !cal.model.features.references(m.dropped))
			rd.fail(p + ".dropped", "must name a thermistor of the main model");
		if (m.features.references(m.dropped)) rd.fail(p, "uses its own dropped thermistor '" + m.dropped + "'");
		cal.fallbacks.push_back(std::move(m));
	}
	const yaml st = rd.child(root, "statistics", "");
	cal.in_sample = readFigures(rd, rd.child(st, "in_sample", "statistics"), "statistics.in_sample");
	cal.held_out = readFigures(rd, rd.child(st, "held_out", "statistics"), "statistics.held_out");
	cal.validation = readFigures(rd, rd.child(st, "validation", "statistics"), "statistics.validation");
	return cal;
}
}  // namespace

Calibration calibrationFromYaml(const std::string& text, const std::string& source)
{
	try
	{
		return parseCalibrationYaml(text, source);
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

void saveCalibrationYaml(const Calibration& cal, const std::string& path)
{
	writeTextFileAtomically(path, calibrationToYaml(cal));
}

Calibration loadCalibrationYaml(const std::string& path)
{
	return calibrationFromYaml(readYamlTextLimited(path), path);
}

}  // namespace mrpt_fog
