/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/ThermalFeatureSet.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace mrpt_fog
{
std::string ThermalSignal::name() const
{
	switch (kind)
	{
		case SignalKind::Temp: return "T(" + a + ")";
		case SignalKind::Rate: return "dT/dt(" + a + ")";
		case SignalKind::Diff: return "dT(" + a + "-" + b + ")";
		case SignalKind::LagRate: return "dTlag/dt(" + a + "," + formatValue("%.17g", tau_s) + ")";
		case SignalKind::Hysteresis:
		{
			// the shortest text that reads back as the same width (1.92, not 1.9199999999999999)
			std::string w;
			for (const char* fmt : {"%.15g", "%.16g", "%.17g"})
				if (std::strtod((w = formatValue(fmt, width_C)).c_str(), nullptr) == width_C) break;
			return "hyst(" + a + (hyst_op == HysteresisOperator::Play ? ",play," : ",branch,") + w + "C)";
		}
		default: return "d/dt dT(" + a + "-" + b + ")";
	}
}

const char* ThermalSignal::unit() const { return isHysteresis() ? "1" : isRate() || isLag() ? "degC/s" : "degC"; }

std::string ThermalTerm::name() const
{
	if (constant) return "1";
	return signal.name() + "^" + std::to_string(power);
}

int ThermalTerm::maxPower(SignalKind kind)
{
	if (kind == SignalKind::Hysteresis) return 1;  // bounded operator: its powers add nothing physical
	return (kind == SignalKind::Rate || kind == SignalKind::DiffRate || kind == SignalKind::LagRate) ? 3 : 5;
}

ThermalTerm ThermalTerm::hysteresis(const std::string& a, HysteresisOperator op, double width_C)
{
	ThermalTerm t = of(SignalKind::Hysteresis, a, "", 1);
	t.signal.hyst_op = op;
	t.signal.width_C = width_C;
	return t;
}

ThermalTerm ThermalTerm::lagRate(const std::string& a, double tau_s, int power)
{
	ThermalTerm t = of(SignalKind::LagRate, a, "", power);
	t.signal.tau_s = tau_s;
	return t;
}

ThermalTerm ThermalTerm::of(SignalKind kind, const std::string& a, const std::string& b, int power)
{
	ThermalTerm t;
	t.constant = false;
	t.signal.kind = kind;
	t.signal.a = a;
	t.signal.b = (kind == SignalKind::Diff || kind == SignalKind::DiffRate) ? b : std::string();
	t.power = power;
	return t;
}

ThermalTerm ThermalTerm::parse(const std::string& text_in)
{
	// Trim; the only inner space allowed is the one of "d/dt dT(".
	const auto b = text_in.find_first_not_of(" \t"), e = text_in.find_last_not_of(" \t");
	std::string text = b == std::string::npos ? std::string() : text_in.substr(b, e - b + 1);
	if (text.rfind("d/dt dT(", 0) == 0) text = "d/dtdT(" + text.substr(8);
	const auto fail = [&](const std::string& why) {
		throw std::invalid_argument("model term '" + text_in + "': " + why +
									" (expected 1, T(a)^k, dT/dt(a)^k, dT(a-b)^k, d/dt dT(a-b)^k, dTlag/dt(a,tau_s)^k, "
									"hyst(a,play,wC)^1 or hyst(a,branch,wC)^1)");
	};
	if (text == "1") return constantTerm();
	struct Form
	{
		const char* prefix;
		SignalKind kind;
	};
	// "d/dtdT(" before "dT(" (its space removed above).
	const Form forms[] = {{"d/dtdT(", SignalKind::DiffRate}, {"dTlag/dt(", SignalKind::LagRate}, {"hyst(", SignalKind::Hysteresis},
						  {"dT/dt(", SignalKind::Rate},
						  {"dT(", SignalKind::Diff}, {"T(", SignalKind::Temp}};
	for (const Form& f : forms)
	{
		const std::string p = f.prefix;
		if (text.compare(0, p.size(), p) != 0) continue;
		const auto close = text.find(')', p.size());
		if (close == std::string::npos) fail("missing ')'");
		const std::string inside = text.substr(p.size(), close - p.size());
		std::string a = inside, b;
		double tau_s = 0;
		if (f.kind == SignalKind::LagRate)
		{
			const auto comma = inside.find(',');
			if (comma == std::string::npos) fail("a lag needs a thermistor and a time constant 'a,tau_s'");
			a = inside.substr(0, comma);
			const std::string t = inside.substr(comma + 1);
			char* end = nullptr;
			tau_s = std::strtod(t.c_str(), &end);
			if (t.empty() || *end != '\0' || !std::isfinite(tau_s) || !(tau_s > 0) || tau_s > 1e7)
				fail("lag time constant '" + t + "' must be a number of seconds in (0, 1e7]");
		}
		HysteresisOperator op = HysteresisOperator::Play;
		double width_C = 0;
		if (f.kind == SignalKind::Hysteresis)
		{
			const auto c1 = inside.find(','), c2 = c1 == std::string::npos ? c1 : inside.find(',', c1 + 1);
			if (c2 == std::string::npos) fail("hysteresis needs a thermistor, an operator and a width 'a,play,2C'");
			a = inside.substr(0, c1);
			const std::string o = inside.substr(c1 + 1, c2 - c1 - 1), w = inside.substr(c2 + 1);
			if (o == "play")
				op = HysteresisOperator::Play;
			else if (o == "branch")
				op = HysteresisOperator::Branch;
			else
				fail("hysteresis operator '" + o + "' must be play or branch");
			char* end = nullptr;
			width_C = std::strtod(w.c_str(), &end);
			if (w.size() < 2 || w.back() != 'C' || end != w.c_str() + w.size() - 1 || !std::isfinite(width_C) ||
				!(width_C > 0) || width_C > 1e3)
				fail("hysteresis width '" + w + "' must be degC written as a number followed by C, in (0, 1000]");
		}
		const bool diff = f.kind == SignalKind::Diff || f.kind == SignalKind::DiffRate;
		if (diff)
		{
			const auto dash = inside.find('-');
			if (dash == std::string::npos) fail("a difference needs two thermistors 'a-b'");
			a = inside.substr(0, dash);
			b = inside.substr(dash + 1);
			if (!isValidThermistorName(b)) fail("bad thermistor name '" + b + "'");
			if (a == b) fail("difference of a thermistor with itself");
		}
		if (!isValidThermistorName(a)) fail("bad thermistor name '" + a + "'");
		int power = 1;
		const std::string rest = text.substr(close + 1);
		if (!rest.empty())
		{
			if (rest[0] != '^' || rest.size() < 2) fail("expected '^k' after ')'");
			const std::string digits = rest.substr(1);
			if (!std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); }))
				fail("power must be an integer");
			power = std::stoi(digits);
		}
		if (power < 1 || power > maxPower(f.kind))
			fail("power " + std::to_string(power) + " outside 1.." + std::to_string(maxPower(f.kind)));
		if (f.kind == SignalKind::LagRate) return lagRate(a, tau_s, power);
		if (f.kind == SignalKind::Hysteresis) return hysteresis(a, op, width_C);
		return of(f.kind, a, b, power);
	}
	fail("unknown form");
	return {};
}

ThermalFeatureSet::ThermalFeatureSet(const std::vector<ThermalTerm>& terms)
{
	terms_.push_back(ThermalTerm::constantTerm());
	for (const auto& t : terms)
	{
		if (t.constant) continue;
		for (const auto& u : terms_)
			if (!u.constant && u.signal == t.signal && u.power == t.power)
				throw std::invalid_argument("model term '" + t.name() + "' appears twice");
		terms_.push_back(t);
	}
	const auto thermIndex = [&](const std::string& n) {
		auto it = std::find(thermistors_.begin(), thermistors_.end(), n);
		if (it != thermistors_.end()) return static_cast<int>(it - thermistors_.begin());
		thermistors_.push_back(n);
		return static_cast<int>(thermistors_.size() - 1);
	};
	for (const auto& t : terms_)
	{
		if (t.constant)
		{
			term_signal_.push_back(-1);
			continue;
		}
		auto it = std::find(signals_.begin(), signals_.end(), t.signal);
		if (it == signals_.end())
		{
			signals_.push_back(t.signal);
			sig_a_.push_back(thermIndex(t.signal.a));
			int b = t.signal.isDifference() ? thermIndex(t.signal.b) : -1;
			if (t.signal.isLag())
			{
				const LagChannel lc{sig_a_.back(), t.signal.tau_s};
				auto l = std::find(lags_.begin(), lags_.end(), lc);
				if (l == lags_.end()) l = lags_.insert(lags_.end(), lc);
				b = static_cast<int>(l - lags_.begin());
			}
			if (t.signal.isHysteresis())
			{
				const HysteresisChannel hc{sig_a_.back(), t.signal.hyst_op, t.signal.width_C};
				auto h = std::find(hyst_.begin(), hyst_.end(), hc);
				if (h == hyst_.end()) h = hyst_.insert(hyst_.end(), hc);
				b = static_cast<int>(h - hyst_.begin());
			}
			sig_b_.push_back(b);
			term_signal_.push_back(static_cast<int>(signals_.size() - 1));
		}
		else
			term_signal_.push_back(static_cast<int>(it - signals_.begin()));
	}
	norm_.assign(signals_.size(), SignalNormalisation{});
}

ThermalFeatureSet ThermalFeatureSet::fromNames(const std::vector<std::string>& names)
{
	std::vector<ThermalTerm> terms;
	for (const auto& n : names) terms.push_back(ThermalTerm::parse(n));
	return ThermalFeatureSet(terms);
}

std::vector<std::string> ThermalFeatureSet::termNames() const
{
	std::vector<std::string> out;
	for (const auto& t : terms_) out.push_back(t.name());
	return out;
}

bool ThermalFeatureSet::references(const std::string& thermistor) const
{
	return std::find(thermistors_.begin(), thermistors_.end(), thermistor) != thermistors_.end();
}

ThermalFeatureSet ThermalFeatureSet::without(const std::string& thermistor) const
{
	std::vector<bool> keep(signals_.size());
	for (std::size_t s = 0; s < signals_.size(); s++) keep[s] = !signals_[s].references(thermistor);
	return selectSignals(keep);
}

ThermalFeatureSet ThermalFeatureSet::selectSignals(const std::vector<bool>& keep) const
{
	std::vector<ThermalTerm> terms;
	for (std::size_t i = 0; i < terms_.size(); i++)
		if (term_signal_[i] >= 0 && keep.at(static_cast<std::size_t>(term_signal_[i]))) terms.push_back(terms_[i]);
	ThermalFeatureSet out(terms);
	for (std::size_t s = 0; s < out.signals_.size(); s++) out.norm_[s] = normalisationOf(out.signals_[s]);
	return out;
}

ThermalFeatureSet ThermalFeatureSet::selectOrders(const std::vector<int>& order) const
{
	std::vector<ThermalTerm> terms;
	for (std::size_t i = 0; i < terms_.size(); i++)
		if (term_signal_[i] >= 0 && terms_[i].power <= order.at(static_cast<std::size_t>(term_signal_[i])))
			terms.push_back(terms_[i]);
	ThermalFeatureSet out(terms);
	for (std::size_t s = 0; s < out.signals_.size(); s++) out.norm_[s] = normalisationOf(out.signals_[s]);
	return out;
}

std::vector<int> ThermalFeatureSet::signalOrders() const
{
	std::vector<int> order(signals_.size(), 0);
	for (std::size_t i = 0; i < terms_.size(); i++)
		if (term_signal_[i] >= 0)
			order[static_cast<std::size_t>(term_signal_[i])] =
				std::max(order[static_cast<std::size_t>(term_signal_[i])], terms_[i].power);
	return order;
}

const SignalNormalisation& ThermalFeatureSet::normalisationOf(const ThermalSignal& s) const
{
	for (std::size_t i = 0; i < signals_.size(); i++)
		if (signals_[i] == s) return norm_[i];
	throw std::out_of_range("signal " + s.name() + " is not in the feature set");
}

void ThermalFeatureSet::signalValues(const double* temp_C, const double* rate_C_s, const double* lag_C_s,
									 const double* hyst, double* v) const
{
	if (!lags_.empty() && !lag_C_s)
		throw std::invalid_argument("feature set reads lag signals (" + std::to_string(lags_.size()) +
									" lags) but no lag values were given");
	if (!hyst_.empty() && !hyst)
		throw std::invalid_argument("feature set reads hysteresis signals (" + std::to_string(hyst_.size()) +
									" operators) but no hysteresis values were given");
	for (std::size_t s = 0; s < signals_.size(); s++)
	{
		const int a = sig_a_[s], b = sig_b_[s];
		switch (signals_[s].kind)
		{
			case SignalKind::Temp: v[s] = temp_C[a]; break;
			case SignalKind::Rate: v[s] = rate_C_s[a]; break;
			case SignalKind::Diff: v[s] = temp_C[a] - temp_C[b]; break;
			case SignalKind::LagRate: v[s] = lag_C_s[b]; break;
			case SignalKind::Hysteresis: v[s] = hyst[b]; break;
			default: v[s] = rate_C_s[a] - rate_C_s[b]; break;
		}
	}
}

int ThermalFeatureSet::features(const double* values, double* f, bool clamp) const
{
	int clamped = 0;
	double z[64];
	const std::size_t ns = signals_.size();
	std::vector<double> zbig;
	double* zp = z;
	if (ns > 64)
	{
		zbig.resize(ns);
		zp = zbig.data();
	}
	for (std::size_t s = 0; s < ns; s++)
	{
		double v = values[s];
		const auto& nm = norm_[s];
		if (clamp && v < nm.min)
		{
			v = nm.min;
			clamped++;
		}
		else if (clamp && v > nm.max)
		{
			v = nm.max;
			clamped++;
		}
		zp[s] = (v - nm.centre) / nm.scale;
	}
	for (std::size_t i = 0; i < terms_.size(); i++)
	{
		const int s = term_signal_[i];
		if (s < 0)
		{
			f[i] = 1.0;
			continue;
		}
		double p = zp[s];
		for (int k = 1; k < terms_[i].power; k++) p *= zp[s];
		f[i] = p;
	}
	return clamped;
}

}  // namespace mrpt_fog
