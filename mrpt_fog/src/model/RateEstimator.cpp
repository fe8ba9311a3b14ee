/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/RateEstimator.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void checkColumns(const std::vector<double>& t, const std::vector<double>& x)
{
	if (t.size() != x.size())
		throw std::invalid_argument("rate estimator: time_s has " + std::to_string(t.size()) + " samples but x has " +
									std::to_string(x.size()));
	for (std::size_t k = 0; k < t.size(); k++)
	{
		if (!std::isfinite(t[k])) throw std::invalid_argument("rate estimator: time_s[" + std::to_string(k) + "] is not finite");
		if (k > 0 && !(t[k] > t[k - 1]))
			throw std::invalid_argument("rate estimator: time_s not strictly increasing at sample " + std::to_string(k));
	}
}
}  // namespace

std::string RateEstimatorSettings::describe() const
{
	std::ostringstream o;
	o << kind << "(window_s=" << window_s;
	if (kind == "savgol") o << ", order=" << poly_order;
	o << ")";
	return o.str();
}

void RateEstimatorSettings::validate() const
{
	if (kind != "causal" && kind != "savgol")
		throw std::invalid_argument("rate estimator kind must be 'causal' or 'savgol', got '" + kind + "'");
	if (!std::isfinite(window_s) || window_s <= 0)
		throw std::invalid_argument("rate estimator window_s must be a positive number of seconds");
	if (kind == "causal" && poly_order != 1)
		throw std::invalid_argument("rate estimator: the causal estimator is a local line (order 1), got order " +
									std::to_string(poly_order));
	if (kind == "savgol" && (poly_order < 1 || poly_order > 4))
		throw std::invalid_argument("rate estimator: savgol order must be 1..4, got " + std::to_string(poly_order));
}

std::unique_ptr<RateEstimator> makeRateEstimator(const RateEstimatorSettings& s)
{
	s.validate();
	if (s.kind == "causal") return std::make_unique<CausalRateEstimator>(s.window_s);
	return std::make_unique<SavitzkyGolayRateEstimator>(s.window_s, s.poly_order);
}

// ---------------------------------------------------------------- CausalRateTracker
CausalRateTracker::CausalRateTracker(std::size_t channels, double window_s)
	: channels_(channels), window_s_(window_s)
{
	if (!std::isfinite(window_s) || window_s <= 0)
		throw std::invalid_argument("CausalRateTracker: window_s must be positive");
	t_.resize(64);
	x_.resize(64 * channels_);
	x_ref_.assign(channels_, 0.0);
	reset();
}

void CausalRateTracker::reset()
{
	head_ = count_ = since_rebuild_ = 0;
	any_ = false;
	t_ref_ = 0.0;
	s1_.assign(channels_, 0.0);
	s2_.assign(channels_, 0.0);
	sx_.assign(channels_, 0.0);
	stx_.assign(channels_, 0.0);
	n_.assign(channels_, 0);
	std::fill(x_ref_.begin(), x_ref_.end(), 0.0);
}

void CausalRateTracker::dropOldest()
{
	const std::size_t cap = t_.size();
	const double dt = t_[head_] - t_ref_;
	const double* xs = &x_[head_ * channels_];
	for (std::size_t c = 0; c < channels_; c++)
	{
		if (std::isnan(xs[c])) continue;
		const double dx = xs[c] - x_ref_[c];
		s1_[c] -= dt;
		s2_[c] -= dt * dt;
		sx_[c] -= dx;
		stx_[c] -= dt * dx;
		n_[c]--;
	}
	head_ = (head_ + 1) % cap;
	count_--;
}

void CausalRateTracker::rebuildSums()
{
	// Exact recomputation relative to fresh references: bounds the round-off of the running
	// add/subtract updates. Called once per buffer turn, so O(1) amortised.
	const std::size_t cap = t_.size();
	t_ref_ = last_t_;
	for (std::size_t c = 0; c < channels_; c++)
	{
		s1_[c] = s2_[c] = sx_[c] = stx_[c] = 0.0;
		n_[c] = 0;
	}
	std::vector<bool> ref_set(channels_, false);
	for (std::size_t i = 0; i < count_; i++)
	{
		const std::size_t slot = (head_ + count_ - 1 - i) % cap;  // newest first: refs = newest value
		const double dt = t_[slot] - t_ref_;
		for (std::size_t c = 0; c < channels_; c++)
		{
			const double x = x_[slot * channels_ + c];
			if (std::isnan(x)) continue;
			if (!ref_set[c])
			{
				x_ref_[c] = x;
				ref_set[c] = true;
			}
			const double dx = x - x_ref_[c];
			s1_[c] += dt;
			s2_[c] += dt * dt;
			sx_[c] += dx;
			stx_[c] += dt * dx;
			n_[c]++;
		}
	}
	since_rebuild_ = 0;
}

void CausalRateTracker::push(double time_s, const double* x)
{
	if (!std::isfinite(time_s)) throw std::invalid_argument("CausalRateTracker: time is not finite");
	if (any_ && !(time_s > last_t_))
		throw std::invalid_argument("CausalRateTracker: time not strictly increasing (" + std::to_string(time_s) +
									" after " + std::to_string(last_t_) + ")");
	if (!any_)
	{
		t_ref_ = time_s;
		for (std::size_t c = 0; c < channels_; c++) x_ref_[c] = std::isnan(x[c]) ? 0.0 : x[c];
		any_ = true;
	}
	last_t_ = time_s;
	// Leave the window (t - window_s, t].
	while (count_ > 0 && t_[head_] <= time_s - window_s_) dropOldest();
	if (count_ == 0)
	{
		t_ref_ = time_s;  // empty window (start or after a gap): fresh time reference
		for (std::size_t c = 0; c < channels_; c++) s1_[c] = s2_[c] = sx_[c] = stx_[c] = 0.0;
	}
	// Grow the ring when full (irregular sampling: the count per window is not known a priori).
	if (count_ == t_.size())
	{
		const std::size_t cap = t_.size();
		std::vector<double> t2(cap * 2), x2(cap * 2 * channels_);
		for (std::size_t i = 0; i < count_; i++)
		{
			const std::size_t slot = (head_ + i) % cap;
			t2[i] = t_[slot];
			for (std::size_t c = 0; c < channels_; c++) x2[i * channels_ + c] = x_[slot * channels_ + c];
		}
		t_.swap(t2);
		x_.swap(x2);
		head_ = 0;
	}
	const std::size_t cap = t_.size();
	const std::size_t slot = (head_ + count_) % cap;
	t_[slot] = time_s;
	double* xs = &x_[slot * channels_];
	const double dt = time_s - t_ref_;
	for (std::size_t c = 0; c < channels_; c++)
	{
		xs[c] = x[c];
		if (std::isnan(x[c])) continue;
		if (n_[c] == 0) x_ref_[c] = x[c];  // window empty for this channel: fresh reference
		const double dx = x[c] - x_ref_[c];
		s1_[c] += dt;
		s2_[c] += dt * dt;
		sx_[c] += dx;
		stx_[c] += dt * dx;
		n_[c]++;
	}
	count_++;
	if (++since_rebuild_ >= cap) rebuildSums();
}

double CausalRateTracker::rate(std::size_t c) const
{
	const double n = static_cast<double>(n_[c]);
	if (n_[c] < 2) return kNaN;
	const double den = n * s2_[c] - s1_[c] * s1_[c];
	if (!(den > 0)) return kNaN;
	return (n * stx_[c] - s1_[c] * sx_[c]) / den;
}

double CausalRateTracker::coveredSpan_s(std::size_t c) const
{
	if (n_[c] < 2) return 0.0;
	const double n = static_cast<double>(n_[c]);
	const double var = s2_[c] / n - (s1_[c] / n) * (s1_[c] / n);
	return var > 0 ? std::sqrt(12.0 * var) : 0.0;
}

// ---------------------------------------------------------------- CausalRateEstimator
CausalRateEstimator::CausalRateEstimator(double window_s) : window_s_(window_s)
{
	RateEstimatorSettings{"causal", window_s, 1}.validate();
}

RateEstimatorSettings CausalRateEstimator::settings() const { return {"causal", window_s_, 1}; }

std::vector<double> CausalRateEstimator::estimate(const std::vector<double>& t, const std::vector<double>& x) const
{
	checkColumns(t, x);
	CausalRateTracker tracker(1, window_s_);
	std::vector<double> out(t.size(), kNaN);
	for (std::size_t k = 0; k < t.size(); k++)
	{
		tracker.push(t[k], &x[k]);
		if (!std::isnan(x[k])) out[k] = tracker.rate(0);
	}
	return out;
}

// ---------------------------------------------------------------- SavitzkyGolayRateEstimator
SavitzkyGolayRateEstimator::SavitzkyGolayRateEstimator(double window_s, int order) : window_s_(window_s), order_(order)
{
	RateEstimatorSettings{"savgol", window_s, order}.validate();
}

RateEstimatorSettings SavitzkyGolayRateEstimator::settings() const { return {"savgol", window_s_, order_}; }

std::vector<double> SavitzkyGolayRateEstimator::estimate(const std::vector<double>& t, const std::vector<double>& x) const
{
	checkColumns(t, x);
	const std::size_t n = t.size();
	std::vector<double> out(n, kNaN);
	const double half = window_s_ / 2;
	std::size_t lo = 0, hi = 0;  // window [lo, hi)
	Eigen::MatrixXd A;
	Eigen::VectorXd b;
	for (std::size_t k = 0; k < n; k++)
	{
		while (t[lo] < t[k] - half) lo++;
		while (hi < n && t[hi] <= t[k] + half) hi++;
		if (std::isnan(x[k])) continue;
		std::size_t valid = 0;
		for (std::size_t i = lo; i < hi; i++)
			if (!std::isnan(x[i])) valid++;
		if (valid < 2) continue;
		// Order reduced where the window holds too few samples (edges, around gaps).
		const int p = static_cast<int>(std::min<std::size_t>(order_, valid - 1));
		const int m = p + 1;
		// Normal equations in u = (t_i - t_k) / half (scaled to [-1, 1]) and x_i - x_k.
		A.setZero(m, m);
		b.setZero(m);
		double pw[10];
		for (std::size_t i = lo; i < hi; i++)
		{
			if (std::isnan(x[i])) continue;
			const double u = (t[i] - t[k]) / half;
			pw[0] = 1.0;
			for (int j = 1; j < 2 * m - 1; j++) pw[j] = pw[j - 1] * u;
			const double dx = x[i] - x[k];
			for (int r = 0; r < m; r++)
			{
				b[r] += pw[r] * dx;
				for (int c = 0; c <= r; c++) A(r, c) += pw[r + c];
			}
		}
		A = A.selfadjointView<Eigen::Lower>();
		const Eigen::VectorXd coef = A.ldlt().solve(b);
		const double r = coef[1] / half;
		if (std::isfinite(r)) out[k] = r;
	}
	return out;
}

}  // namespace mrpt_fog
