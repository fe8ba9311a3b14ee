/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/ThermistorHealth.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/common/NumberFormat.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;

void requireField(bool ok, const char* field, const char* reason)
{
	if (!ok) throw std::invalid_argument(std::string("thermistor health: ") + field + ": " + reason);
}

std::string timeText(double t) { return formatValue("%.17g", t); }
}  // namespace

const char* toString(ThermistorState s)
{
	switch (s)
	{
		case ThermistorState::Ok: return "ok";
		case ThermistorState::Dropout: return "dropout";
		case ThermistorState::OutOfRange: return "out_of_range";
		case ThermistorState::Spike: return "spike";
		case ThermistorState::Stuck: return "stuck";
	}
	return "?";
}

void ThermistorHealthSettings::validate() const
{
	requireField(std::isfinite(valid_min_C) && std::isfinite(valid_max_C) && valid_min_C < valid_max_C,
				 "valid_min_C/valid_max_C", "must be finite with min < max");
	requireField(std::isfinite(spike_jump_C) && spike_jump_C > 0, "spike_jump_C", "must be > 0");
	requireField(std::isfinite(max_rate_C_per_s) && max_rate_C_per_s >= 0, "max_rate_C_per_s", "must be >= 0");
	requireField(std::isfinite(spike_max_duration_s) && spike_max_duration_s >= 0, "spike_max_duration_s",
				 "must be >= 0");
	requireField(std::isfinite(stuck_window_s) && stuck_window_s > 0, "stuck_window_s", "must be > 0");
	requireField(stuck_min_samples >= 2, "stuck_min_samples", "must be >= 2");
	requireField(std::isfinite(stuck_tolerance_C) && stuck_tolerance_C >= 0, "stuck_tolerance_C", "must be >= 0");
	requireField(std::isfinite(stuck_peer_change_C) && stuck_peer_change_C > stuck_tolerance_C, "stuck_peer_change_C",
				 "must be > stuck_tolerance_C");
}

ThermistorHealth::ThermistorHealth(std::size_t thermistor_count, const ThermistorHealthSettings& settings)
	: settings_(settings), ch_(thermistor_count), raw_(thermistor_count)
{
	settings_.validate();
	reset();
}

void ThermistorHealth::reset()
{
	for (auto& c : ch_)
	{
		c = Channel{};
		c.peer_at_run_start.assign(ch_.size(), kNaN);
	}
	first_ = true;
	last_t_ = 0;
}

void ThermistorHealth::startRun(std::size_t i, double t, double value, const double* v)
{
	Channel& c = ch_[i];
	c.has_run = true;
	c.run_value_C = value;
	c.run_start_t = t;
	c.run_samples = 1;
	for (std::size_t j = 0; j < ch_.size(); j++) c.peer_at_run_start[j] = (j == i) ? kNaN : v[j];
}

bool ThermistorHealth::step(double time_s, double* temp_C)
{
	if (!std::isfinite(time_s)) throw std::invalid_argument("thermistor health: time " + timeText(time_s) + " s is not finite");
	if (!first_ && !(time_s > last_t_))
		throw std::invalid_argument("thermistor health: time " + timeText(time_s) +
									" s does not increase (previous " + timeText(last_t_) + " s)");
	first_ = false;
	last_t_ = time_s;
	const auto& s = settings_;
	bool rejected = false;

	// Pass 1: range and spike screening of each reading on its own history.
	for (std::size_t i = 0; i < ch_.size(); i++)
	{
		Channel& c = ch_[i];
		const double x = temp_C[i];
		double v = x;
		if (std::isnan(x))
			c.state = ThermistorState::Dropout;
		else if (!std::isfinite(x) || x < s.valid_min_C || x > s.valid_max_C)
		{
			c.state = ThermistorState::OutOfRange;
			v = kNaN;
		}
		else if (c.has_accepted &&
				 std::abs(x - c.accepted_C) > s.spike_jump_C + s.max_rate_C_per_s * (time_s - c.accepted_t))
		{
			if (!c.in_excursion)
			{
				c.in_excursion = true;
				c.excursion_start_t = time_s;
			}
			if (time_s - c.excursion_start_t >= s.spike_max_duration_s)
			{
				// the reading stayed away: accept it as a new level
				c.in_excursion = false;
				c.accepted_C = x;
				c.accepted_t = time_s;
				c.counters.level_changes++;
				c.state = ThermistorState::Ok;
			}
			else
			{
				c.state = ThermistorState::Spike;
				v = kNaN;
			}
		}
		else
		{
			c.in_excursion = false;
			c.has_accepted = true;
			c.accepted_C = x;
			c.accepted_t = time_s;
			c.state = ThermistorState::Ok;
		}
		raw_[i] = v;  // readings after pass 1 (what the peers of pass 2 see)
	}

	// Pass 2: stuck detection against the peers' (pass-1 screened) readings.
	for (std::size_t i = 0; i < ch_.size(); i++)
	{
		Channel& c = ch_[i];
		const double v = raw_[i];
		if (c.state == ThermistorState::Ok)
		{
			const bool same = c.has_run && std::abs(v - c.run_value_C) <= s.stuck_tolerance_C;
			if (c.stuck && same)
				c.state = ThermistorState::Stuck;
			else if (!same)
			{
				c.stuck = false;
				startRun(i, time_s, v, raw_.data());
			}
			else
			{
				c.run_samples++;
				double moved = 0;
				for (std::size_t j = 0; j < ch_.size(); j++)
				{
					if (j == i || std::isnan(raw_[j])) continue;
					if (std::isnan(c.peer_at_run_start[j])) c.peer_at_run_start[j] = raw_[j];
					moved = std::max(moved, std::abs(raw_[j] - c.peer_at_run_start[j]));
				}
				if (time_s - c.run_start_t >= s.stuck_window_s && c.run_samples >= s.stuck_min_samples &&
					moved >= s.stuck_peer_change_C)
				{
					c.stuck = true;
					c.counters.stuck_events++;
					c.state = ThermistorState::Stuck;
				}
			}
			if (c.state == ThermistorState::Stuck)
				c.has_accepted = false;  // its recovery is not judged against the stuck value
		}
		switch (c.state)
		{
			case ThermistorState::Ok: c.counters.ok++; break;
			case ThermistorState::Dropout: c.counters.dropout++; break;
			case ThermistorState::OutOfRange: c.counters.out_of_range++; break;
			case ThermistorState::Spike: c.counters.spike++; break;
			case ThermistorState::Stuck: c.counters.stuck++; break;
		}
		if (c.state != ThermistorState::Ok && c.state != ThermistorState::Dropout)
		{
			temp_C[i] = kNaN;
			rejected = true;
		}
	}
	return rejected;
}

ThermistorScreening screenThermistors(FogSeries& series, const ThermistorHealthSettings& settings)
{
	const std::size_t n = series.thermistorCount();
	if (series.temp_C.size() != n)
		throw std::invalid_argument("thermistor health: " + std::to_string(series.temp_C.size()) +
									" temperature columns for " + std::to_string(n) + " thermistors");
	for (std::size_t i = 0; i < n; i++)
		if (series.temp_C[i].size() != series.size())
			throw std::invalid_argument("thermistor health: column " + series.thermistors[i].name + " has " +
										std::to_string(series.temp_C[i].size()) + " samples, time has " +
										std::to_string(series.size()));
	ThermistorHealth health(n, settings);
	ThermistorScreening out;
	std::vector<double> row(n);
	for (std::size_t k = 0; k < series.size(); k++)
	{
		for (std::size_t i = 0; i < n; i++) row[i] = series.temp_C[i][k];
		health.step(series.time_s[k], row.data());
		for (std::size_t i = 0; i < n; i++) series.temp_C[i][k] = row[i];
	}
	for (std::size_t i = 0; i < n; i++)
	{
		out.names.push_back(series.thermistors[i].name);
		out.counters.push_back(health.counters(i));
		const auto& c = health.counters(i);
		out.rejected_readings += c.out_of_range + c.spike + c.stuck;
	}
	return out;
}

}  // namespace mrpt_fog
