/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/obs/FogSeriesLayout.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace mrpt_fog
{
constexpr EnumName<CoilSide> kCoilSides[] = {
	{CoilSide::Inner, "inner"}, {CoilSide::Outer, "outer"}, {CoilSide::Other, "other"}};

const char* toString(CoilSide side) { return nameIn(kCoilSides, side, "other"); }

CoilSide coilSideFromString(const std::string& text)
{
	std::string t = text;
	std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
	if (const auto side = valueIn(kCoilSides, t)) return *side;
	throw std::invalid_argument("coil side must be inner, outer or other, got '" + text + "'");
}

char axisLetter(GyroAxis axis) { return static_cast<char>('x' + static_cast<int>(axis)); }

bool isValidThermistorName(const std::string& name)
{
	return !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
		return std::isalnum(c) || c == '_';
	});
}

int FogSeries::thermistorIndex(const std::string& name) const
{
	for (std::size_t i = 0; i < thermistors.size(); i++)
		if (thermistors[i].name == name) return static_cast<int>(i);
	return -1;
}

GyroAxis FogSeries::primaryAxis() const
{
	for (int a = 0; a < 3; a++)
		if (has_axis[a]) return static_cast<GyroAxis>(a);
	throw std::invalid_argument("FOG series has no sensitive axis");
}

const std::vector<double>& FogSeries::primaryRate_dph() const
{
	return rate_dph[static_cast<int>(primaryAxis())];
}

std::string FogSeries::metadataValue(const std::string& key, const std::string& fallback) const
{
	for (const auto& kv : metadata)
		if (kv.first == key) return kv.second;
	return fallback;
}

void FogSeries::setMetadata(const std::string& key, const std::string& value)
{
	for (auto& kv : metadata)
		if (kv.first == key)
		{
			kv.second = value;
			return;
		}
	metadata.emplace_back(key, value);
}

std::vector<std::size_t> FogSeries::turnOnSamples() const
{
	std::vector<std::size_t> on;
	for (std::size_t k = 1; k < power.size(); k++)
		if (power[k] != 0.0 && power[k - 1] == 0.0) on.push_back(k);
	return on;
}

void FogSeries::resize(std::size_t n)
{
	time_s.resize(n, 0.0);
	for (int a = 0; a < 3; a++)
		if (has_axis[a]) rate_dph[a].resize(n, 0.0);
	temp_C.resize(thermistors.size());
	for (auto& col : temp_C) col.resize(n, std::nan(""));
	if (!table_rate_dph.empty()) table_rate_dph.resize(n, 0.0);
	if (!field_uT.empty()) field_uT.resize(n, 0.0);
	if (!power.empty()) power.resize(n, 1.0);
}

void FogSeries::appendSampleFrom(const FogSeries& o, std::size_t k)
{
	time_s.push_back(o.time_s.at(k));
	for (int a = 0; a < 3; a++)
		if (has_axis[a]) rate_dph[a].push_back(o.rate_dph[a].at(k));
	temp_C.resize(thermistors.size());
	for (std::size_t i = 0; i < thermistors.size(); i++) temp_C[i].push_back(o.temp_C.at(i).at(k));
	if (!o.table_rate_dph.empty()) table_rate_dph.push_back(o.table_rate_dph[k]);
	if (!o.field_uT.empty()) field_uT.push_back(o.field_uT[k]);
	if (!o.power.empty()) power.push_back(o.power[k]);
}

void FogSeries::validate() const
{
	const std::size_t n = time_s.size();
	auto fail = [](const std::string& msg) { throw std::invalid_argument(msg); };
	if (!has_axis[0] && !has_axis[1] && !has_axis[2]) fail("FOG series: no sensitive axis present");
	for (int a = 0; a < 3; a++)
	{
		const std::string col = std::string("rate_") + axisLetter(static_cast<GyroAxis>(a)) + "_dph";
		if (has_axis[a] && rate_dph[a].size() != n)
			fail("FOG series: column " + col + " has " + std::to_string(rate_dph[a].size()) +
				 " samples, time_s has " + std::to_string(n));
		if (!has_axis[a] && !rate_dph[a].empty()) fail("FOG series: column " + col + " filled but axis absent");
		if (has_axis[a])
			for (std::size_t k = 0; k < n; k++)
				if (!std::isfinite(rate_dph[a][k]) && !(std::isnan(rate_dph[a][k]) && power.size() == n && power[k] == 0.0))
					fail("FOG series: non-finite " + col + " at sample " + std::to_string(k) +
						 (std::isnan(rate_dph[a][k]) ? " (a missing rate is allowed only where power is 0)" : ""));
	}
	if (temp_C.size() != thermistors.size())
		fail("FOG series: " + std::to_string(thermistors.size()) + " thermistors but " +
			 std::to_string(temp_C.size()) + " temperature columns");
	std::set<std::string> names;
	for (std::size_t i = 0; i < thermistors.size(); i++)
	{
		const auto& t = thermistors[i];
		if (!isValidThermistorName(t.name))
			fail("FOG series: invalid thermistor name '" + t.name + "' (use letters, digits, _)");
		if (!names.insert(t.name).second) fail("FOG series: duplicate thermistor name '" + t.name + "'");
		if (temp_C[i].size() != n)
			fail("FOG series: column temp_" + t.name + "_C has " + std::to_string(temp_C[i].size()) +
				 " samples, time_s has " + std::to_string(n));
		for (std::size_t k = 0; k < n; k++)
			if (std::isinf(temp_C[i][k]))
				fail("FOG series: infinite temp_" + t.name + "_C at sample " + std::to_string(k));
	}
	auto checkOptional = [&](const std::vector<double>& v, const char* col) {
		if (!v.empty() && v.size() != n)
			fail(std::string("FOG series: column ") + col + " has " + std::to_string(v.size()) +
				 " samples, time_s has " + std::to_string(n));
	};
	checkOptional(table_rate_dph, "table_rate_dph");
	checkOptional(field_uT, "field_uT");
	checkOptional(power, "power");
	for (std::size_t k = 0; k < n; k++)
	{
		if (!std::isfinite(time_s[k])) fail("FOG series: non-finite time_s at sample " + std::to_string(k));
		if (k > 0 && !(time_s[k] > time_s[k - 1]))
			fail("FOG series: time_s not strictly increasing at sample " + std::to_string(k) + " (" +
				 std::to_string(time_s[k - 1]) + " s then " + std::to_string(time_s[k]) + " s)");
	}
}

bool FogSeries::sameLayout(const FogSeries& o) const
{
	return thermistors == o.thermistors && has_axis == o.has_axis;
}

FogSeries emptySeriesLike(const FogSeries& h)
{
	FogSeries s;
	s.sensor_label = h.sensor_label;
	s.epoch_s = h.epoch_s;
	s.thermistors = h.thermistors;
	s.has_axis = h.has_axis;
	s.metadata = h.metadata;
	s.temp_C.assign(h.thermistors.size(), {});
	return s;
}

FogSeries layoutHeaderOf(const FogSeries& s, bool has_table_rate, bool has_field, bool has_power)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	FogSeries h = emptySeriesLike(s);
	if (has_table_rate) h.table_rate_dph.assign(1, nan);
	if (has_field) h.field_uT.assign(1, nan);
	if (has_power) h.power.assign(1, nan);
	return h;
}

}  // namespace mrpt_fog
