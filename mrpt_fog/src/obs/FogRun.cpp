/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/obs/FogRun.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/FogSeriesLayout.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;
}

/** The samples: a series in memory, or rows in a spill file (the layout of `layout`). */
struct FogRunStorage
{
	const FogSeries* view = nullptr;
	FogSeries layout;  // layout of the rows (axes, thermistors); no samples
	bool table = false, field = false, power = false;
	std::optional<RowSpill> rows;
	std::vector<double> row;  // append() scratch

	std::size_t width() const
	{
		std::size_t w = 1 + layout.thermistors.size() + table + field + power;
		for (int a = 0; a < 3; a++) w += layout.has_axis[a];
		return w;
	}
};

struct FogRun::Impl
{
	std::shared_ptr<FogRunStorage> st;
	FogSeries header;  // layout + metadata, optional columns flagged by one NaN
	double front = kNaN, back = kNaN;
	int only_axis = -1;  // axisView(): the axis kept
	double subtract_dph = 0.0;

	bool table() const { return st->table; }
	bool field() const { return st->field; }
	bool power() const { return st->power; }
	/** axisView()'s change of a chunk. */
	void transform(FogSeries& c) const
	{
		if (only_axis < 0) return;
		for (int a = 0; a < 3; a++)
			if (a != only_axis)
			{
				std::vector<double>().swap(c.rate_dph[a]);
				c.has_axis[a] = false;
			}
		if (subtract_dph != 0.0)
		{
			auto& rate = c.rate_dph[only_axis];
			for (std::size_t k = 0; k < rate.size(); k++)
				if (c.gyroOn(k) && std::isfinite(rate[k])) rate[k] -= subtract_dph;
		}
	}
};


FogRun::FogRun(const FogSeries& s) : impl_(std::make_unique<Impl>())
{
	impl_->st = std::make_shared<FogRunStorage>();
	auto& st = *impl_->st;
	st.view = &s;
	st.table = !s.table_rate_dph.empty();
	st.field = !s.field_uT.empty();
	st.power = !s.power.empty();
	st.layout = layoutHeaderOf(s, st.table, st.field, st.power);
	impl_->header = st.layout;
	if (!s.empty())
	{
		impl_->front = s.time_s.front();
		impl_->back = s.time_s.back();
	}
}

FogRun::FogRun(const FogSeries& header, bool has_table_rate, bool has_field, bool has_power)
	: impl_(std::make_unique<Impl>())
{
	impl_->st = std::make_shared<FogRunStorage>();
	auto& st = *impl_->st;
	st.table = has_table_rate;
	st.field = has_field;
	st.power = has_power;
	st.layout = layoutHeaderOf(header, has_table_rate, has_field, has_power);
	impl_->header = st.layout;
	st.rows.emplace(st.width());
	st.row.resize(st.width());
}

FogRun::FogRun(FogRun&&) noexcept = default;
FogRun& FogRun::operator=(FogRun&&) noexcept = default;
FogRun::~FogRun() = default;

void FogRun::append(const FogSeries& c, std::size_t j)
{
	auto& st = *impl_->st;
	if (!st.rows || impl_->only_axis >= 0) throw std::logic_error("FogRun::append on a view");
	auto& r = st.row;
	std::size_t w = 0;
	r[w++] = c.time_s[j];
	for (int a = 0; a < 3; a++)
		if (st.layout.has_axis[a]) r[w++] = c.rate_dph[a][j];
	for (const auto& col : c.temp_C) r[w++] = col[j];
	if (st.table) r[w++] = c.table_rate_dph[j];
	if (st.field) r[w++] = c.field_uT[j];
	if (st.power) r[w++] = c.power[j];
	st.rows->push(r.data());
	if (st.rows->rows() == 1) impl_->front = c.time_s[j];
	impl_->back = c.time_s[j];
}

const FogSeries& FogRun::header() const { return impl_->header; }
std::size_t FogRun::size() const { return impl_->st->view ? impl_->st->view->size() : impl_->st->rows->rows(); }
double FogRun::frontTime_s() const { return impl_->front; }
double FogRun::backTime_s() const { return impl_->back; }
bool FogRun::hasTableRate() const { return impl_->table(); }
bool FogRun::hasField() const { return impl_->field(); }
bool FogRun::hasPower() const { return impl_->power(); }
const FogSeries* FogRun::inMemory() const { return impl_->only_axis < 0 ? impl_->st->view : nullptr; }

void FogRun::forEachChunk(const std::function<void(const FogSeries&, std::size_t)>& f) const
{
	const FogRunStorage& st = *impl_->st;
	if (st.view)
	{
		const FogSeries& s = *st.view;
		if (impl_->only_axis < 0)
		{
			if (!s.empty()) f(s, 0);
			return;
		}
		// A transformed view: copies of slices of the series.
		FogSeries chunk = st.layout;
		for (std::size_t k0 = 0; k0 < s.size(); k0 += kChunkSamples)
		{
			const std::size_t n = std::min(kChunkSamples, s.size() - k0);
			const auto slice = [&](std::vector<double>& to, const std::vector<double>& from) {
				to.assign(from.begin() + static_cast<std::ptrdiff_t>(k0), from.begin() + static_cast<std::ptrdiff_t>(k0 + n));
			};
			chunk.has_axis = st.layout.has_axis;
			slice(chunk.time_s, s.time_s);
			for (int a = 0; a < 3; a++)
				if (chunk.has_axis[a]) slice(chunk.rate_dph[a], s.rate_dph[a]);
			for (std::size_t i = 0; i < chunk.temp_C.size(); i++) slice(chunk.temp_C[i], s.temp_C[i]);
			if (st.table) slice(chunk.table_rate_dph, s.table_rate_dph);
			if (st.field) slice(chunk.field_uT, s.field_uT);
			if (st.power) slice(chunk.power, s.power);
			impl_->transform(chunk);
			f(chunk, k0);
		}
		return;
	}
	FogSeries chunk = st.layout;
	const std::size_t width = st.width();
	st.rows->forEachBlock([&](const double* rows, std::size_t n, std::size_t first) {
		chunk.has_axis = st.layout.has_axis;
		chunk.time_s.resize(n);
		for (int a = 0; a < 3; a++)
			if (chunk.has_axis[a]) chunk.rate_dph[a].resize(n);
		for (auto& col : chunk.temp_C) col.resize(n);
		if (st.table) chunk.table_rate_dph.resize(n);
		if (st.field) chunk.field_uT.resize(n);
		if (st.power) chunk.power.resize(n);
		for (std::size_t j = 0; j < n; j++)
		{
			const double* r = rows + j * width;
			std::size_t w = 0;
			chunk.time_s[j] = r[w++];
			for (int a = 0; a < 3; a++)
				if (chunk.has_axis[a]) chunk.rate_dph[a][j] = r[w++];
			for (auto& col : chunk.temp_C) col[j] = r[w++];
			if (st.table) chunk.table_rate_dph[j] = r[w++];
			if (st.field) chunk.field_uT[j] = r[w++];
			if (st.power) chunk.power[j] = r[w++];
		}
		impl_->transform(chunk);
		f(chunk, first);
	});
}

FogSeries FogRun::load() const
{
	if (inMemory()) return *inMemory();
	FogSeries s = impl_->header;
	s.table_rate_dph.clear();
	s.field_uT.clear();
	s.power.clear();
	s.time_s.reserve(size());
	forEachChunk([&](const FogSeries& c, std::size_t) {
		const auto add = [](std::vector<double>& to, const std::vector<double>& from) {
			to.insert(to.end(), from.begin(), from.end());
		};
		add(s.time_s, c.time_s);
		for (int a = 0; a < 3; a++)
			if (s.has_axis[a]) add(s.rate_dph[a], c.rate_dph[a]);
		for (std::size_t i = 0; i < s.temp_C.size(); i++) add(s.temp_C[i], c.temp_C[i]);
		if (impl_->table()) add(s.table_rate_dph, c.table_rate_dph);
		if (impl_->field()) add(s.field_uT, c.field_uT);
		if (impl_->power()) add(s.power, c.power);
	});
	return s;
}

void FogRun::validate() const
{
	if (impl_->st->view) impl_->st->view->validate();
}

FogRun FogRun::axisView(GyroAxis axis, double subtract_dph) const
{
	const int a = static_cast<int>(axis);
	if (!impl_->header.has_axis[a]) throw std::invalid_argument(std::string("FogRun: no ") + axisLetter(axis) + " axis");
	FogRun v(*this, 0);
	v.impl_->only_axis = a;
	v.impl_->subtract_dph = subtract_dph;
	for (int b = 0; b < 3; b++) v.impl_->header.has_axis[b] = b == a;
	return v;
}

FogRun::FogRun(const FogRun& o, int) : impl_(std::make_unique<Impl>(*o.impl_)) {}

}  // namespace mrpt_fog
