/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/RunSignals.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
std::size_t RunSignals::usableCount() const
{
	return static_cast<std::size_t>(std::count(usable.begin(), usable.end(), 1));
}

namespace
{
double median(std::vector<double> v)
{
	if (v.empty()) return 0.0;
	const auto mid = v.begin() + static_cast<long>(v.size() / 2);
	std::nth_element(v.begin(), mid, v.end());
	return *mid;
}

bool varies(const std::vector<double>& v)
{
	if (v.empty()) return false;
	const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
	return *hi - *lo > 1e-9;
}

/** Bridges NaN runs shorter than max_s by linear interpolation between finite neighbours in
 * the same time block; returns the column with remaining NaNs. */
std::vector<double> bridgeDropouts(const std::vector<double>& t, std::vector<double> y,
								   const std::vector<int>& timeBlock, double max_s)
{
	const std::size_t n = y.size();
	std::size_t k = 0;
	while (k < n)
	{
		if (std::isfinite(y[k]))
		{
			++k;
			continue;
		}
		std::size_t e = k;
		while (e < n && !std::isfinite(y[e])) ++e;
		if (k > 0 && e < n && timeBlock[k - 1] == timeBlock[e] && t[e] - t[k - 1] <= max_s)
		{
			for (std::size_t j = k; j < e; ++j)
			{
				const double w = (t[j] - t[k - 1]) / (t[e] - t[k - 1]);
				y[j] = (1 - w) * y[k - 1] + w * y[e];
			}
		}
		k = e;
	}
	return y;
}
}  // namespace

std::vector<double> localSlopePerMin(const std::vector<double>& time_s, const std::vector<double>& y,
									 const std::vector<int>& block, double window_s)
{
	const std::size_t n = y.size();
	std::vector<double> out(n, 0.0);
	const double half = 0.5 * window_s;
	std::size_t lo = 0, hi = 0;
	for (std::size_t k = 0; k < n; ++k)
	{
		if (block[k] < 0) continue;
		// window [lo, hi) within the same block
		if (lo > k) lo = k;
		while (lo < k && (time_s[k] - time_s[lo] > half || block[lo] != block[k])) ++lo;
		if (hi < k + 1) hi = k + 1;
		while (hi < n && time_s[hi] - time_s[k] <= half && block[hi] == block[k]) ++hi;
		while (hi > k + 1 && (time_s[hi - 1] - time_s[k] > half || block[hi - 1] != block[k])) --hi;
		double st = 0, sy = 0;
		std::size_t m = 0;
		for (std::size_t j = lo; j < hi; ++j)
		{
			st += time_s[j];
			sy += y[j];
			++m;
		}
		if (m < 2)
		{
			continue;
		}
		const double tm = st / m, ym = sy / m;
		double stt = 0, sty = 0;
		for (std::size_t j = lo; j < hi; ++j)
		{
			stt += (time_s[j] - tm) * (time_s[j] - tm);
			sty += (time_s[j] - tm) * (y[j] - ym);
		}
		out[k] = stt > 0 ? 60.0 * sty / stt : 0.0;
	}
	return out;
}

RunSignals computeRunSignals(const FogSeries& run, const RunSignalsOptions& opt)
{
	run.validate();
	const std::size_t n = run.size();
	if (n < 20) throw std::invalid_argument("run has " + std::to_string(n) + " samples; need at least 20");
	if (run.thermistorCount() == 0) throw std::invalid_argument("run has no thermistor column");

	RunSignals s;
	s.time_s = run.time_s;
	std::vector<double> dts;
	for (std::size_t k = 1; k < n; ++k) dts.push_back(run.time_s[k] - run.time_s[k - 1]);
	s.dt_s = median(dts);

	// time blocks (gaps split them)
	std::vector<int> timeBlock(n, 0);
	for (std::size_t k = 1; k < n; ++k)
		timeBlock[k] = timeBlock[k - 1] + ((run.time_s[k] - run.time_s[k - 1] > 3.0 * s.dt_s) ? 1 : 0);

	const auto& rate = run.primaryRate_dph();
	s.has_table = run.table_rate_dph.size() == n && varies(run.table_rate_dph);
	s.has_field = run.field_uT.size() == n && varies(run.field_uT);
	s.has_power = run.power.size() == n;
	s.table_rate_dph = run.table_rate_dph.size() == n ? run.table_rate_dph : std::vector<double>(n, 0.0);
	s.field_uT = run.field_uT.size() == n ? run.field_uT : std::vector<double>(n, 0.0);
	s.power = s.has_power ? run.power : std::vector<double>(n, 1.0);
	s.bias_dph.resize(n);
	for (std::size_t k = 0; k < n; ++k) s.bias_dph[k] = rate[k] - s.table_rate_dph[k];

	// thermistors: bridge dropouts
	const std::size_t nt = run.thermistorCount();
	s.thermistor_C.resize(nt);
	for (std::size_t i = 0; i < nt; ++i)
		s.thermistor_C[i] = bridgeDropouts(run.time_s, run.temp_C[i], timeBlock, opt.max_dropout_bridge_s);

	// usability: powered, every thermistor known
	s.usable.assign(n, 1);
	for (std::size_t k = 0; k < n; ++k)
	{
		if (s.power[k] < 0.5) s.usable[k] = 0;
		for (std::size_t i = 0; i < nt; ++i)
			if (!std::isfinite(s.thermistor_C[i][k])) s.usable[k] = 0;
	}
	// blocks: contiguous usable samples in the same time block
	s.block.assign(n, -1);
	int b = -1;
	for (std::size_t k = 0; k < n; ++k)
	{
		if (!s.usable[k]) continue;
		if (k == 0 || !s.usable[k - 1] || timeBlock[k] != timeBlock[k - 1]) ++b;
		s.block[k] = b;
	}
	// power-on instants: start of each powered stretch (run start included)
	for (std::size_t k = 0; k < n; ++k)
		if (s.power[k] >= 0.5 && (k == 0 || s.power[k - 1] < 0.5)) s.power_on_s.push_back(run.time_s[k]);

	// mean / inner / outer
	std::size_t nIn = 0, nOut = 0, nOther = 0;
	for (const auto& th : run.thermistors)
	{
		nIn += th.side == CoilSide::Inner;
		nOut += th.side == CoilSide::Outer;
		nOther += th.side == CoilSide::Other;
	}
	s.has_inner_outer = nIn > 0 && nOut > 0;
	s.has_other = nOther > 0;
	const double nan = std::numeric_limits<double>::quiet_NaN();
	s.temp_mean_C.assign(n, nan);
	s.temp_inner_C.assign(n, nan);
	s.temp_outer_C.assign(n, nan);
	for (std::size_t k = 0; k < n; ++k)
	{
		double sm = 0, si = 0, so = 0;
		for (std::size_t i = 0; i < nt; ++i)
		{
			const double T = s.thermistor_C[i][k];
			sm += T;
			if (run.thermistors[i].side == CoilSide::Inner) si += T;
			if (run.thermistors[i].side == CoilSide::Outer) so += T;
		}
		s.temp_mean_C[k] = sm / nt;
		s.temp_inner_C[k] = s.has_inner_outer ? si / nIn : s.temp_mean_C[k];
		s.temp_outer_C[k] = s.has_inner_outer ? so / nOut : s.temp_mean_C[k];
	}
	s.gradient_C.resize(n);
	for (std::size_t k = 0; k < n; ++k) s.gradient_C[k] = s.temp_inner_C[k] - s.temp_outer_C[k];
	s.temp_coil_C = s.temp_mean_C;
	if (s.has_other && nIn + nOut > 0)
		for (std::size_t k = 0; k < n; ++k)
		{
			double sc = 0;
			for (std::size_t i = 0; i < nt; ++i)
				if (run.thermistors[i].side != CoilSide::Other) sc += s.thermistor_C[i][k];
			s.temp_coil_C[k] = sc / static_cast<double>(nIn + nOut);
		}
	if (s.has_inner_outer && s.has_other)
	{
		s.outer_other_C.assign(n, nan);
		for (std::size_t k = 0; k < n; ++k)
		{
			double so = 0;
			for (std::size_t i = 0; i < nt; ++i)
				if (run.thermistors[i].side == CoilSide::Other) so += s.thermistor_C[i][k];
			s.outer_other_C[k] = s.temp_outer_C[k] - so / static_cast<double>(nOther);
		}
	}

	// derivatives need finite values: replace unusable samples by 0 (never used: block -1)
	auto finiteOrZero = [](std::vector<double> v)
	{
		for (auto& x : v)
			if (!std::isfinite(x)) x = 0.0;
		return v;
	};
	const double w = std::max(opt.derivative_window_s, 2.5 * s.dt_s);
	s.dtemp_dt_Cpm = localSlopePerMin(s.time_s, finiteOrZero(s.temp_mean_C), s.block, w);
	s.dtemp_coil_dt_Cpm = s.temp_coil_C == s.temp_mean_C
							  ? s.dtemp_dt_Cpm
							  : localSlopePerMin(s.time_s, finiteOrZero(s.temp_coil_C), s.block, w);
	s.dgradient_dt_Cpm = localSlopePerMin(s.time_s, finiteOrZero(s.gradient_C), s.block, w);
	s.dthermistor_dt_Cpm.resize(nt);
	for (std::size_t i = 0; i < nt; ++i)
		s.dthermistor_dt_Cpm[i] = localSlopePerMin(s.time_s, finiteOrZero(s.thermistor_C[i]), s.block, w);
	return s;
}

}  // namespace mrpt_fog::discrepancy
