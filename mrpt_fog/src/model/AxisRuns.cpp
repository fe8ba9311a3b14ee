/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/AxisRuns.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
std::string letter(GyroAxis a) { return std::string(1, axisLetter(a)); }

bool appliesTableRates(const FogSeries& r)
{
	for (std::size_t k = 0; k < r.table_rate_dph.size(); k++)
		if (r.table_rate_dph[k] != 0.0 && r.gyroOn(k)) return true;
	return false;
}
}  // namespace

GyroAxis tableAxis(const FogSeries& run)
{
	const std::string t = run.metadataValue("table_axis");
	if (t.empty()) return run.primaryAxis();
	if (t != "x" && t != "y" && t != "z")
		throw std::invalid_argument("metadata table_axis: '" + t + "' is not x, y or z");
	return static_cast<GyroAxis>(t[0] - 'x');
}

std::vector<GyroAxis> commonAxes(const std::vector<FogSeries>& runs)
{
	std::vector<GyroAxis> out;
	for (GyroAxis a : {GyroAxis::X, GyroAxis::Y, GyroAxis::Z})
	{
		bool all = !runs.empty();
		for (const auto& r : runs) all &= r.has_axis[static_cast<std::size_t>(a)];
		if (all) out.push_back(a);
	}
	return out;
}

AxisRunSet runsForAxis(std::vector<FogSeries>& runs, const std::vector<std::string>& labels, GyroAxis axis, bool consume)
{
	AxisRunSet set;
	set.axis = axis;
	const std::size_t ai = static_cast<std::size_t>(axis);
	const std::string key = "earth_rate_dph." + letter(axis);
	int stated = 0, unstated = 0;
	std::string first_stated, first_unstated;
	for (std::size_t r = 0; r < runs.size(); r++)
	{
		const std::string label = r < labels.size() ? labels[r] : "run " + std::to_string(r + 1);
		FogSeries& run = runs[r];
		if (!run.has_axis[ai])
		{
			set.skipped.push_back(label + ": has no " + letter(axis) + " axis");
			continue;
		}
		GyroAxis table;
		try
		{
			table = tableAxis(run);
		}
		catch (const std::invalid_argument& e)
		{
			throw std::invalid_argument(label + ": " + e.what());
		}
		if (table != axis && appliesTableRates(run))
		{
			set.skipped.push_back(label + ": its table turns about " + letter(table) + ", not " + letter(axis) +
								  " (the " + letter(axis) + " output holds a turning Earth-rate projection there)");
			continue;
		}
		const std::string e_text = run.metadataValue(key);
		(e_text.empty() ? unstated : stated)++;
		if (e_text.empty() && first_unstated.empty()) first_unstated = label;
		if (!e_text.empty() && first_stated.empty()) first_stated = label;
		FogSeries s = consume ? std::move(run) : run;
		for (std::size_t a = 0; a < 3; a++)
			if (a != ai)
			{
				std::vector<double>().swap(s.rate_dph[a]);
				s.has_axis[a] = false;
			}
		if (!e_text.empty())
		{
			char* end = nullptr;
			const double e = std::strtod(e_text.c_str(), &end);
			if (!std::isfinite(e) || *end != '\0')
				throw std::invalid_argument(label + ": metadata " + key + ": '" + e_text + "' is not a rate [deg/h]");
			auto& rate = s.rate_dph[ai];
			for (std::size_t k = 0; k < rate.size(); k++)
				if (s.gyroOn(k) && std::isfinite(rate[k])) rate[k] -= e;
		}
		set.runs.push_back(std::move(s));
		set.labels.push_back(label);
	}
	if (stated > 0 && unstated > 0)
		throw std::invalid_argument(first_unstated + ": metadata " + key + " missing, but " + first_stated +
									" states it: the Earth rate would be removed from some runs' bias and not from "
									"others'; state it for every run of axis " + letter(axis) + " or for none");
	set.earth_rate_removed = stated > 0;
	return set;
}

std::vector<GyroAxis> commonAxes(const std::vector<FogRun>& runs)
{
	std::vector<FogSeries> headers;
	for (const auto& r : runs) headers.push_back(r.header());
	return commonAxes(headers);
}

AxisRunViews runsForAxis(const std::vector<FogRun>& runs, const std::vector<std::string>& labels, GyroAxis axis)
{
	// The choice is made on the headers (metadata, axes) and on whether a run applies table
	// rates (one pass); the samples are then seen through axis views.
	std::vector<FogSeries> heads;
	for (const auto& r : runs)
	{
		FogSeries h = r.header();
		h.table_rate_dph.clear();
		h.power.clear();
		bool applies = false;
		r.forEachChunk([&](const FogSeries& c, std::size_t) {
			if (!applies) applies = appliesTableRates(c);
		});
		if (applies)  // one sample that applies a table rate stands for the run
		{
			h.time_s.assign(1, 0.0);
			h.table_rate_dph.assign(1, 1.0);
			for (auto& col : h.temp_C) col.assign(1, 0.0);
			for (int a = 0; a < 3; a++)
				if (h.has_axis[a]) h.rate_dph[a].assign(1, 0.0);
		}
		else
			h.field_uT.clear();
		heads.push_back(std::move(h));
	}
	AxisRunSet set = runsForAxis(heads, labels, axis, true);
	AxisRunViews out;
	out.axis = axis;
	out.skipped = set.skipped;
	out.earth_rate_removed = set.earth_rate_removed;
	const std::string key = "earth_rate_dph." + letter(axis);
	std::size_t r = 0;  // the kept runs, in order
	for (const auto& label : set.labels)
		for (; r < runs.size(); r++)
			if ((r < labels.size() ? labels[r] : "run " + std::to_string(r + 1)) == label && runs[r].header().has_axis[static_cast<std::size_t>(axis)])
			{
				const std::string e = runs[r].header().metadataValue(key);
				out.runs.push_back(runs[r].axisView(axis, e.empty() ? 0.0 : std::strtod(e.c_str(), nullptr)));
				out.labels.push_back(label);
				r++;
				break;
			}
	return out;
}

}  // namespace mrpt_fog
