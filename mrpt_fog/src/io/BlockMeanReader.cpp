/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/io/BlockMeanReader.h>
#include <mrpt_fog/io/FogLogIO.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;
constexpr std::size_t kPeriodSteps = 64;  // time steps used for the native period
constexpr std::size_t kStepReservoir = 65536;  // thermistor steps kept for the quantum

bool sameValue(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

/** Sums of one block (temperatures in the accumulator's flat arrays). */
struct Block
{
	double t_sum = 0, t_first = 0, t_last = 0;
	std::size_t count = 0;
	std::array<double, 3> rate_sum{{0, 0, 0}};
	double table = kNaN, field = kNaN, power = kNaN;  // constant over a block
};
}  // namespace

struct BlockMeanAccumulator::Impl
{
	FogSeries layout;
	BlockMeanOptions opt;
	std::size_t n_th = 0;
	std::vector<FogSample> pending;  // the first samples, until the period is known
	bool period_known = false;
	double period_s = 0, gap_s = INFINITY;
	std::size_t k_nominal = 1;  // samples per block now (K x 2^doublings)
	int doublings = 0;
	std::size_t cascade_at = 0;  // rows that trigger the next merge
	std::size_t samples = 0;
	double prev_t = -INFINITY;

	std::vector<Block> rows;
	std::vector<double> temp_sum;  // rows x n_th
	std::vector<std::size_t> temp_count;
	bool open = false;
	Block cur;
	std::vector<double> cur_temp_sum;
	std::vector<std::size_t> cur_temp_count;
	// raw thermistor steps (the quantum): previous reading, a reservoir of the non-zero steps
	std::vector<double> prev_temp;
	std::vector<double> steps;
	std::size_t steps_seen = 0;
	std::mt19937_64 rng{20261202};

	void noteSteps(const FogSample& x)
	{
		for (std::size_t i = 0; i < n_th; i++)
		{
			const double d = std::fabs(x.temp_C[i] - prev_temp[i]);
			prev_temp[i] = x.temp_C[i];
			if (!(std::isfinite(d) && d > 0)) continue;
			steps_seen++;
			if (steps.size() < kStepReservoir) steps.push_back(d);
			else
			{
				const std::uint64_t j = rng() % steps_seen;
				if (j < kStepReservoir) steps[j] = d;
			}
		}
	}

	bool unlimited() const { return !(opt.min_block_s > 0); }

	void decidePeriod()
	{
		std::vector<double> d;
		for (std::size_t i = 1; i < pending.size(); i++) d.push_back(pending[i].time_s - pending[i - 1].time_s);
		if (!d.empty())
		{
			std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
			period_s = d[d.size() / 2];
		}
		period_known = true;
		gap_s = period_s > 0 ? 3.0 * period_s : INFINITY;
		k_nominal = 1;
		if (!unlimited() && period_s > 0)
		{
			const double r = opt.min_block_s / period_s * (1.0 + 1e-4);  // 10 Hz read as 9.99999 Hz
			k_nominal = r >= 1.0 ? static_cast<std::size_t>(std::min(r, 1e9)) : 1;
		}
		cascade_at = unlimited() ? std::numeric_limits<std::size_t>::max() : std::max<std::size_t>(opt.max_rows, 2) / 2 * 2;
		std::vector<FogSample> p;
		p.swap(pending);
		for (const auto& x : p) feed(x);
	}

	void start(const FogSample& x)
	{
		cur = Block{};
		cur.t_sum = cur.t_first = cur.t_last = x.time_s;
		cur.count = 1;
		for (int a = 0; a < 3; a++) cur.rate_sum[a] = x.rate_dph[a];
		cur.table = x.table_rate_dph;
		cur.field = x.field_uT;
		cur.power = x.power;
		for (std::size_t i = 0; i < n_th; i++)
		{
			const bool ok = std::isfinite(x.temp_C[i]);
			cur_temp_sum[i] = ok ? x.temp_C[i] : 0.0;
			cur_temp_count[i] = ok ? 1 : 0;
		}
		open = true;
	}

	void close()
	{
		if (!open) return;
		rows.push_back(cur);
		temp_sum.insert(temp_sum.end(), cur_temp_sum.begin(), cur_temp_sum.end());
		temp_count.insert(temp_count.end(), cur_temp_count.begin(), cur_temp_count.end());
		open = false;
		// an even count, so that every row finds its pair and the blocks stay uniform
		if (rows.size() >= cascade_at && rows.size() % 2 == 0) cascade();
	}

	bool mergeable(const Block& a, const Block& b) const
	{
		return sameValue(a.power, b.power) && sameValue(a.table, b.table) && sameValue(a.field, b.field) &&
			   b.t_first - a.t_last <= gap_s;
	}

	/** Merges adjacent rows in pairs (in place). */
	void cascade()
	{
		if (opt.max_block_s > 0 && static_cast<double>(2 * k_nominal) * period_s > opt.max_block_s * (1.0 + 1e-9))
		{
			cascade_at = std::numeric_limits<std::size_t>::max();  // blocks at their longest: rows grow
			return;
		}
		std::size_t out = 0, merged = 0;
		for (std::size_t i = 0; i < rows.size();)
		{
			const bool pair = i + 1 < rows.size() && mergeable(rows[i], rows[i + 1]);
			Block b = rows[i];
			for (std::size_t j = 0; j < n_th; j++)
			{
				temp_sum[out * n_th + j] = temp_sum[i * n_th + j];
				temp_count[out * n_th + j] = temp_count[i * n_th + j];
			}
			if (pair)
			{
				const Block& c = rows[i + 1];
				b.t_sum += c.t_sum;
				b.t_last = c.t_last;
				b.count += c.count;
				for (int a = 0; a < 3; a++) b.rate_sum[a] += c.rate_sum[a];
				for (std::size_t j = 0; j < n_th; j++)
				{
					temp_sum[out * n_th + j] += temp_sum[(i + 1) * n_th + j];
					temp_count[out * n_th + j] += temp_count[(i + 1) * n_th + j];
				}
				merged++;
			}
			rows[out++] = b;
			i += pair ? 2 : 1;
		}
		rows.resize(out);
		temp_sum.resize(out * n_th);
		temp_count.resize(out * n_th);
		if (merged > 0)
		{
			doublings++;
			k_nominal *= 2;
		}
		// rows that could not merge (power / table / field changes) stay: try again only once
		// the rows have grown by half the limit, so that a log of many changes costs O(n log n)
		cascade_at = std::max(cascade_at, out + std::max<std::size_t>(opt.max_rows / 2, 1));
	}

	void feed(const FogSample& x)
	{
		const bool powered = !(x.power == 0.0);
		if (powered)
			for (int a = 0; a < 3; a++)
				if (layout.has_axis[a] && !std::isfinite(x.rate_dph[a]))
					throw std::invalid_argument("sample " + std::to_string(samples) + " (t = " + std::to_string(x.time_s) +
												" s): the gyro is powered but its rate is not finite");
		if (open && (cur.count >= k_nominal || !sameValue(cur.power, x.power) || !sameValue(cur.table, x.table_rate_dph) ||
					 !sameValue(cur.field, x.field_uT) || x.time_s - prev_t > gap_s))
			close();
		if (!open) start(x);
		else
		{
			cur.t_sum += x.time_s;
			cur.t_last = x.time_s;
			cur.count++;
			for (int a = 0; a < 3; a++) cur.rate_sum[a] += x.rate_dph[a];
			for (std::size_t i = 0; i < n_th; i++)
				if (std::isfinite(x.temp_C[i]))
				{
					cur_temp_sum[i] += x.temp_C[i];
					cur_temp_count[i]++;
				}
		}
		prev_t = x.time_s;
		samples++;
	}
};

BlockMeanAccumulator::BlockMeanAccumulator(const FogSeries& layout, const BlockMeanOptions& opt)
	: impl_(std::make_unique<Impl>())
{
	impl_->layout = layout;
	impl_->opt = opt;
	impl_->n_th = layout.thermistors.size();
	impl_->cur_temp_sum.assign(impl_->n_th, 0.0);
	impl_->cur_temp_count.assign(impl_->n_th, 0);
	impl_->prev_temp.assign(impl_->n_th, kNaN);
}

BlockMeanAccumulator::~BlockMeanAccumulator() = default;

void BlockMeanAccumulator::add(const FogSample& x)
{
	if (x.temp_C.size() != impl_->n_th)
		throw std::invalid_argument("block means: a sample with " + std::to_string(x.temp_C.size()) +
									" thermistors, the layout has " + std::to_string(impl_->n_th));
	impl_->noteSteps(x);
	if (impl_->period_known)
	{
		impl_->feed(x);
		return;
	}
	impl_->pending.push_back(x);
	if (impl_->pending.size() > kPeriodSteps) impl_->decidePeriod();
}

FogSeries BlockMeanAccumulator::finish(BlockMeanInfo& info)
{
	Impl& m = *impl_;
	if (!m.period_known) m.decidePeriod();
	m.close();
	FogSeries out = emptySeriesLike(m.layout);
	const std::size_t n = m.rows.size();
	out.time_s.resize(n);
	for (int a = 0; a < 3; a++)
		if (out.has_axis[a]) out.rate_dph[a].resize(n);
	for (auto& col : out.temp_C) col.resize(n);
	const bool has_table = !m.layout.table_rate_dph.empty(), has_field = !m.layout.field_uT.empty(),
			   has_power = !m.layout.power.empty();
	if (has_table) out.table_rate_dph.resize(n);
	if (has_field) out.field_uT.resize(n);
	if (has_power) out.power.resize(n);
	for (std::size_t r = 0; r < n; r++)
	{
		const Block& b = m.rows[r];
		const double c = static_cast<double>(b.count);
		out.time_s[r] = m.opt.row_time == BlockMeanOptions::RowTime::FirstSample ? b.t_first : b.t_sum / c;
		for (int a = 0; a < 3; a++)
			if (out.has_axis[a]) out.rate_dph[a][r] = b.rate_sum[a] / c;
		for (std::size_t i = 0; i < m.n_th; i++)
		{
			const std::size_t ci = m.temp_count[r * m.n_th + i];
			out.temp_C[i][r] = ci > 0 ? m.temp_sum[r * m.n_th + i] / static_cast<double>(ci) : kNaN;
		}
		if (has_table) out.table_rate_dph[r] = b.table;
		if (has_field) out.field_uT[r] = b.field;
		if (has_power) out.power[r] = b.power;
	}
	info = BlockMeanInfo{};
	info.samples = m.samples;
	info.rows = n;
	info.native_period_s = m.period_s;
	info.samples_per_block = m.k_nominal;
	info.block_s = static_cast<double>(m.k_nominal) * m.period_s;
	info.doublings = m.doublings;
	if (m.steps.size() >= 20)
	{
		// percentile(steps, 0.05) as the analysis takes it: element floor(0.05 (n - 1)) in order
		const auto kth = m.steps.begin() + static_cast<std::ptrdiff_t>(std::floor(0.05 * static_cast<double>(m.steps.size() - 1)));
		std::nth_element(m.steps.begin(), kth, m.steps.end());
		info.thermistor_step_p05_C = *kth;
	}
	m.rows.clear();
	m.rows.shrink_to_fit();
	return out;
}

FogSeries readFogLogBlockMeans(const std::string& path, const std::string& fog_label, const BlockMeanOptions& opt,
							   BlockMeanInfo& info,
							   const std::function<void(double, double*, std::size_t)>& each,
							   const std::function<void(std::uint64_t, std::uint64_t, std::uint64_t)>& progress,
							   const LogReadOptions& options)
{
	FogLogReader reader(path, fog_label, ReadLimits{}, nullptr, options);
	const FogSeries& h = reader.header();
	BlockMeanAccumulator acc(h, opt);
	FogSample x;
	try
	{
		while (reader.next(x))
		{
			if (each) each(x.time_s, x.temp_C.data(), x.temp_C.size());
			acc.add(x);
			if (progress) progress(reader.samplesRead(), reader.fileBytesRead(), reader.fileBytes());
		}
		FogSeries out = acc.finish(info);
		out.validate();
		return out;
	}
	catch (const std::invalid_argument& e)
	{
		throw FogIoError(path + ": sensor '" + h.sensor_label + "': " + e.what());
	}
}

}  // namespace mrpt_fog
