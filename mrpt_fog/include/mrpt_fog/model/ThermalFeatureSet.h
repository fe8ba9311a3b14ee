/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ThermalFeatureSet.h
 * The regressors of the bias model, by name. A term is a power of one thermal signal:
 *
 *   `1`                   constant
 *   `T(Ti1)^k`            temperature of thermistor Ti1, k = 1..5
 *   `dT/dt(Ti1)^k`        its rate, k = 1..3
 *   `dT(Ti1-To1)^k`       difference of two thermistors (e.g. inner - outer), k = 1..5
 *   `d/dt dT(Ti1-To1)^k`  rate of that difference, k = 1..3
 *   `dTlag/dt(Ti1,400)^k` rate of Ti1's reading passed through a first-order lag of time
 *                         constant 400 s (LagFilter.h: what a point inside the coil sees of a
 *                         boundary sensor), k = 1..3; needs the lag state (lag values below)
 *   `hyst(Ti1,play,2C)^1` hysteresis of Ti1's reading (HysteresisFilter.h): a play (backlash)
 *                         operator of half-width 2 degC, output in [-1, 1]; power 1 only
 *   `hyst(Ti1,branch,5C)^1` the exponential branch of span 5 degC (behind the filter's dead
 *                         band); power 1 only; both need the operators' state (hysteresis
 *                         values below), exist from the first reading (no rate window)
 *
 * ("^1" may be omitted when parsing; names are always printed with it.)
 * Never raw powers of degC: every signal v is normalised, z = (v - centre) / scale, with centre
 * and scale chosen at calibration so that z spans [-1, 1] over the calibration data (rates and
 * differences: centre 0, scale = max |v|), and the term is z^k (dimensionless). The calibrated
 * range [min, max] of each signal is stored with it; evaluation can clamp to it so a 5th-order
 * polynomial is never extrapolated. A hysteresis output is bounded by construction: centre 0,
 * scale 1, range [-1, 1] (it is never clamped).
 */

#include <mrpt_fog/model/HysteresisFilter.h>
#include <mrpt_fog/model/LagFilter.h>

#include <limits>
#include <string>
#include <vector>

namespace mrpt_fog
{
enum class SignalKind : unsigned char
{
	Temp = 0,  //!< T(a) [degC]
	Rate = 1,  //!< dT/dt(a) [degC/s]
	Diff = 2,  //!< T(a) - T(b) [degC]
	DiffRate = 3,  //!< d/dt (T(a) - T(b)) [degC/s]
	LagRate = 4,  //!< d/dt of T(a) through a first-order lag of tau_s (LagFilter.h) [degC/s]
	Hysteresis = 5  //!< T(a) through a hysteresis operator of width_C (HysteresisFilter.h) [1], in [-1, 1]
};

/** One thermal signal: a thermistor's temperature or rate, or a difference of two. */
struct ThermalSignal
{
	SignalKind kind = SignalKind::Temp;
	std::string a, b;  //!< thermistor names (b only for differences)
	double tau_s = 0;  //!< lag time constant [s] (LagRate only, else 0)
	HysteresisOperator hyst_op = HysteresisOperator::Play;  //!< Hysteresis only (else Play)
	double width_C = 0;  //!< play half-width or branch span [degC] (Hysteresis only, else 0)

	/** "T(a)", "dT/dt(a)", "dT(a-b)", "d/dt dT(a-b)", "dTlag/dt(a,tau)", "hyst(a,play,wC)",
	 * "hyst(a,branch,wC)". */
	std::string name() const;
	/** "degC", "degC/s" or "1" (hysteresis: dimensionless). */
	const char* unit() const;
	/** A rate from the causal rate estimator (its window: start-up, burst logs). A lag rate is not
	 * one: it exists from the first reading (LagFilter.h). */
	bool isRate() const { return kind == SignalKind::Rate || kind == SignalKind::DiffRate; }
	bool isLag() const { return kind == SignalKind::LagRate; }
	/** A hysteresis operator's output: exists from the first reading, bounded to [-1, 1]. */
	bool isHysteresis() const { return kind == SignalKind::Hysteresis; }
	bool isDifference() const { return kind == SignalKind::Diff || kind == SignalKind::DiffRate; }
	bool references(const std::string& thermistor) const { return a == thermistor || (isDifference() && b == thermistor); }
	bool operator==(const ThermalSignal& o) const
	{
		return kind == o.kind && a == o.a && b == o.b && tau_s == o.tau_s && hyst_op == o.hyst_op && width_C == o.width_C;
	}
};

/** A model term: constant, or signal^power. */
struct ThermalTerm
{
	bool constant = true;
	ThermalSignal signal;
	int power = 0;

	std::string name() const;
	/** Parses a term name (see file comment). Throws std::invalid_argument naming the text and
	 * what is wrong (unknown form, bad thermistor name, power out of 1..max for the kind). */
	static ThermalTerm parse(const std::string& text);
	/** Highest power allowed for a signal kind (5 for temperatures/differences, 3 for rates, 1
	 * for hysteresis). */
	static int maxPower(SignalKind kind);
	static ThermalTerm constantTerm() { return ThermalTerm{}; }
	static ThermalTerm of(SignalKind kind, const std::string& a, const std::string& b, int power);
	/** dTlag/dt(a,tau_s)^power. */
	static ThermalTerm lagRate(const std::string& a, double tau_s, int power);
	/** hyst(a,play|branch,width_C)^1. */
	static ThermalTerm hysteresis(const std::string& a, HysteresisOperator op, double width_C);
};

/** Normalisation and calibrated range of one signal (units of the signal). */
struct SignalNormalisation
{
	double centre = 0.0;
	double scale = 1.0;  //!< > 0
	double min = -std::numeric_limits<double>::infinity();  //!< calibrated range
	double max = std::numeric_limits<double>::infinity();
};

/** An ordered list of terms (the constant is always term 0) with per-signal normalisation. */
class ThermalFeatureSet
{
   public:
	ThermalFeatureSet() : ThermalFeatureSet(std::vector<ThermalTerm>{}) {}
	/** Adds the constant as term 0 if absent. Throws std::invalid_argument on a repeated term. */
	explicit ThermalFeatureSet(const std::vector<ThermalTerm>& terms);
	/** Parses names (see ThermalTerm::parse). */
	static ThermalFeatureSet fromNames(const std::vector<std::string>& names);

	std::size_t termCount() const { return terms_.size(); }
	const std::vector<ThermalTerm>& terms() const { return terms_; }
	std::vector<std::string> termNames() const;
	/** Thermistors referenced, in order of first appearance. */
	const std::vector<std::string>& thermistors() const { return thermistors_; }
	/** Distinct signals, in order of first appearance. */
	const std::vector<ThermalSignal>& signals() const { return signals_; }
	/** Signal index of term i (-1 for the constant). */
	int termSignal(std::size_t i) const { return term_signal_[i]; }
	bool references(const std::string& thermistor) const;
	/** The same set without every term that references `thermistor` (a fallback model). */
	ThermalFeatureSet without(const std::string& thermistor) const;
	/** The subset of terms whose signal index is in `signal_keep` (true = kept; constant kept). */
	ThermalFeatureSet selectSignals(const std::vector<bool>& signal_keep) const;
	/** The subset of terms whose power is <= order[signal] (0 drops the signal; constant kept). */
	ThermalFeatureSet selectOrders(const std::vector<int>& order) const;
	/** Highest power of each signal in the set. */
	std::vector<int> signalOrders() const;

	std::vector<SignalNormalisation>& normalisation() { return norm_; }
	const std::vector<SignalNormalisation>& normalisation() const { return norm_; }
	/** Normalisation of the signal with this name (throws std::out_of_range if absent). */
	const SignalNormalisation& normalisationOf(const ThermalSignal& s) const;

	/** The first-order lags the lag signals read (thermistor index in thermistors() order, time
	 * constant), distinct, in order of first appearance: the channels of the LagFilterBank that
	 * supplies signalValues' lag rates. */
	const std::vector<LagChannel>& lags() const { return lags_; }
	/** The hysteresis operators the hysteresis signals read (thermistor index in thermistors()
	 * order, operator, width), distinct, in order of first appearance: the channels of the
	 * HysteresisFilterBank that supplies signalValues' hysteresis values. */
	const std::vector<HysteresisChannel>& hystereses() const { return hyst_; }
	/** Signal values from per-thermistor temperatures [degC] and rates [degC/s], both indexed in
	 * thermistors() order, the lag rates [degC/s] in lags() order and the hysteresis outputs in
	 * hystereses() order (each may be null when the set reads none; throws std::invalid_argument
	 * when it is null and the set reads such signals). */
	void signalValues(const double* temp_C, const double* rate_C_s, double* values) const
	{
		signalValues(temp_C, rate_C_s, nullptr, nullptr, values);
	}
	void signalValues(const double* temp_C, const double* rate_C_s, const double* lag_rate_C_s, double* values) const
	{
		signalValues(temp_C, rate_C_s, lag_rate_C_s, nullptr, values);
	}
	void signalValues(const double* temp_C, const double* rate_C_s, const double* lag_rate_C_s, const double* hyst,
					  double* values) const;
	/** Features (termCount() values) from signal values. With clamp, values outside the
	 * calibrated range are clamped to it; returns how many signals were clamped. A NaN value
	 * gives NaN features. */
	int features(const double* values, double* f, bool clamp) const;

   private:
	std::vector<ThermalTerm> terms_;
	std::vector<std::string> thermistors_;
	std::vector<ThermalSignal> signals_;
	std::vector<int> term_signal_;
	std::vector<int> sig_a_, sig_b_;  // thermistor index of each signal's a and b (LagRate: b = lag index, Hysteresis: its operator)
	std::vector<LagChannel> lags_;
	std::vector<HysteresisChannel> hyst_;
	std::vector<SignalNormalisation> norm_;
};

}  // namespace mrpt_fog
