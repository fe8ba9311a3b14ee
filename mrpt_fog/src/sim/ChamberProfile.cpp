/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/ChamberProfile.h>

#include <mrpt/containers/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "YamlFields.h"

namespace mrpt_fog::sim
{
using namespace detail;

namespace
{
using mrpt_fog::units::kSecondsPerMinute;

/** IEEE Std 952 style scale-factor-vs-temperature run: soaks at -40, -15, 10, 35 and 60 C
 * (2 C/min between them, 90 min soak each: about 2 coil time constants), then at each soak the
 * table turns at +-1, +-10 and +-100 deg/s for 4 min each (both signs, so that bias and scale
 * factor separate); 10.9 h. Gyro on and settled at the start. */
std::string rateTableProfileYaml()
{
	std::string yaml =
		"name: ratetable\n"
		"initial_temp_C: 25\n"
		"power_initially: true\n"
		"initial_state: steady\n"
		"segments:\n";
	for (const char* soak_C : {"-40", "-15", "10", "35", "60"})
	{
		yaml += std::string("  - {type: ramp, to_C: ") + soak_C + ", rate_C_per_min: 2}\n";
		yaml += "  - {type: hold, duration_min: 90}\n";
		for (const char* rate_dph : {"3600", "-3600", "36000", "-36000", "360000", "-360000"})
		{
			yaml += std::string("  - {type: table, rate_dph: ") + rate_dph + "}\n";
			yaml += "  - {type: hold, duration_min: 4}\n";
		}
		yaml += "  - {type: table, rate_dph: 0}\n";
	}
	return yaml;
}

// The built-in profiles, as the YAML users would write.
const std::map<std::string, std::string>& presetTable()
{
	static const std::map<std::string, std::string> table = {
		{"seed",
		 // The seed paper's chamber run: 25 -> -40 C at 1 C/min, soak 2 h, -> 60 C at 1 C/min,
		 // soak 2 h (65 + 120 + 100 + 120 min = 6.75 h). Gyro on and settled at the start.
		 "name: seed\n"
		 "initial_temp_C: 25\n"
		 "power_initially: true\n"
		 "initial_state: steady\n"
		 "segments:\n"
		 "  - {type: ramp, to_C: -40, rate_C_per_min: 1}\n"
		 "  - {type: hold, duration_min: 120}\n"
		 "  - {type: ramp, to_C: 60, rate_C_per_min: 1}\n"
		 "  - {type: hold, duration_min: 120}\n"},
		{"calibration",
		 // One chamber run that calibrates the bias model, its rate terms and the warm-up: a
		 // turn-on from unpowered equilibrium at 25 C (2 h: the warm-up; fog-calibrate keeps the
		 // first hour out of the bias fit), the seed's ramps and soaks, then a +-20 C sine of
		 // 30 min period and 2 and 3 C/min ramps, which the seed's 1 C/min ramps leave out
		 // (docs/validation/generalization.md, "One calibration run"); 12.8 h.
		 "name: calibration\n"
		 "initial_temp_C: 25\n"
		 "power_initially: true\n"
		 "initial_state: cold\n"
		 "segments:\n"
		 "  - {type: hold, duration_min: 120}\n"
		 "  - {type: ramp, to_C: -40, rate_C_per_min: 1}\n"
		 "  - {type: hold, duration_min: 120}\n"
		 "  - {type: ramp, to_C: 60, rate_C_per_min: 1}\n"
		 "  - {type: hold, duration_min: 120}\n"
		 "  - {type: ramp, to_C: 5, rate_C_per_min: 2}\n"
		 "  - {type: sine, amplitude_C: 20, period_min: 30, cycles: 3}\n"
		 "  - {type: ramp, to_C: -35, rate_C_per_min: 2}\n"
		 "  - {type: hold, duration_min: 45}\n"
		 "  - {type: ramp, to_C: 55, rate_C_per_min: 3}\n"
		 "  - {type: hold, duration_min: 45}\n"},
		{"B",
		 // Held-out validation: other rates (0.5, 2, 1.5 C/min), a step, a log-swept sine.
		 "name: B\n"
		 "initial_temp_C: 20\n"
		 "power_initially: true\n"
		 "initial_state: steady\n"
		 "segments:\n"
		 "  - {type: hold, duration_min: 20}\n"
		 "  - {type: ramp, to_C: -30, rate_C_per_min: 0.5}\n"
		 "  - {type: hold, duration_min: 60}\n"
		 "  - {type: step, to_C: -10}\n"
		 "  - {type: hold, duration_min: 45}\n"
		 "  - {type: ramp, to_C: 50, rate_C_per_min: 2}\n"
		 "  - {type: hold, duration_min: 50}\n"
		 "  - {type: sweep, amplitude_C: 8, period_start_min: 60, period_end_min: 4, duration_min: 90}\n"
		 "  - {type: ramp, to_C: 25, rate_C_per_min: 1.5}\n"
		 "  - {type: hold, duration_min: 40}\n"},
		{"warmup",
		 // Room-temperature turn-on: unpowered equilibrium, power on at t = 0, 3 h.
		 "name: warmup\n"
		 "initial_temp_C: 23\n"
		 "power_initially: true\n"
		 "initial_state: cold\n"
		 "segments:\n"
		 "  - {type: hold, duration_min: 180}\n"},
		{"rich",
		 // For the model-gap work: steps, sines and a sweep near the coil time constants
		 // (1-40 min), power cycles, rate-table and magnetic-field segments.
		 "name: rich\n"
		 "initial_temp_C: 25\n"
		 "power_initially: true\n"
		 "initial_state: steady\n"
		 "segments:\n"
		 "  - {type: hold, duration_min: 20}\n"
		 "  - {type: step, to_C: 0}\n"
		 "  - {type: hold, duration_min: 40}\n"
		 "  - {type: power, on: false}\n"
		 "  - {type: hold, duration_min: 30}\n"
		 "  - {type: power, on: true}\n"
		 "  - {type: hold, duration_min: 40}\n"
		 "  - {type: ramp, to_C: 20, rate_C_per_min: 3}\n"
		 "  - {type: sine, amplitude_C: 10, period_min: 20, cycles: 3}\n"
		 "  - {type: sweep, amplitude_C: 10, period_start_min: 40, period_end_min: 1, duration_min: 150}\n"
		 "  - {type: table, rate_dph: 36000}\n"
		 "  - {type: hold, duration_min: 10}\n"
		 "  - {type: table, rate_dph: -36000}\n"
		 "  - {type: hold, duration_min: 10}\n"
		 "  - {type: table, rate_dph: 0}\n"
		 "  - {type: field, field_uT: 500}\n"
		 "  - {type: hold, duration_min: 15}\n"
		 "  - {type: field, field_uT: -500}\n"
		 "  - {type: hold, duration_min: 15}\n"
		 "  - {type: field, field_uT: 0}\n"
		 "  - {type: ramp, to_C: 50, rate_C_per_min: 0.5}\n"
		 "  - {type: hold, duration_min: 30}\n"
		 "  - {type: step, to_C: 30}\n"
		 "  - {type: hold, duration_min: 60}\n"
		 "  - {type: power, on: false}\n"
		 "  - {type: hold, duration_min: 20}\n"
		 "  - {type: power, on: true}\n"
		 "  - {type: hold, duration_min: 60}\n"},
		{"drive_cabin_mild",
		 // Vehicle cabin, autumn morning: soaked at 8 C, gyro and heater on at t = 0, cabin
		 // warms to 21 C at 1 C/min; 70.5 min (for drives other than the bundled one).
		 "name: drive_cabin_mild\n"
		 "initial_temp_C: 8\n"
		 "power_initially: true\n"
		 "initial_state: cold\n"
		 "segments:\n"
		 "  - {type: hold, duration_min: 2}\n"
		 "  - {type: ramp, to_C: 21, rate_C_per_min: 1}\n"
		 "  - {type: hold, duration_min: 55.5}\n"},
		{"drive_cabin_hot",
		 // Vehicle cabin, summer: sun-soaked at 40 C, gyro and air conditioning on at t = 0,
		 // cabin cools to 22 C at 1.5 C/min; 70.5 min.
		 "name: drive_cabin_hot\n"
		 "initial_temp_C: 40\n"
		 "power_initially: true\n"
		 "initial_state: cold\n"
		 "segments:\n"
		 "  - {type: hold, duration_min: 1}\n"
		 "  - {type: ramp, to_C: 22, rate_C_per_min: 1.5}\n"
		 "  - {type: hold, duration_min: 57.5}\n"},
		{"ratetable", rateTableProfileYaml()},
		{"drive_cabin",
		 // Vehicle cabin on a winter cold start: soaked at -15 C, gyro and heater on at t = 0,
		 // cabin warms to 20 C at 2 C/min, then slowly to 24 C (sun); 70.5 min.
		 "name: drive_cabin\n"
		 "initial_temp_C: -15\n"
		 "power_initially: true\n"
		 "initial_state: cold\n"
		 "segments:\n"
		 "  - {type: hold, duration_min: 3}\n"
		 "  - {type: ramp, to_C: 20, rate_C_per_min: 2}\n"
		 "  - {type: hold, duration_min: 25}\n"
		 "  - {type: ramp, to_C: 24, rate_C_per_min: 0.2}\n"
		 "  - {type: hold, duration_min: 5}\n"},
	};
	return table;
}

ProfileSegment parseSegment(const mrpt::containers::yaml& node, const std::string& where)
{
	if (!node.isMap()) fieldError(where, "expected a map such as {type: hold, duration_min: 10}");
	const std::string type = readString(node, "type", where, "");
	ProfileSegment s;
	if (type == "hold")
	{
		checkKeys(node, {"type", "duration_min"}, where);
		s.kind = ProfileSegment::Kind::Hold;
		s.duration_s = readPositive(node, "duration_min", where) * kSecondsPerMinute;
	}
	else if (type == "ramp")
	{
		checkKeys(node, {"type", "to_C", "rate_C_per_min"}, where);
		s.kind = ProfileSegment::Kind::Ramp;
		s.to_C = readNumber(node, "to_C", where);
		s.value = readPositive(node, "rate_C_per_min", where);
	}
	else if (type == "step")
	{
		checkKeys(node, {"type", "to_C"}, where);
		s.kind = ProfileSegment::Kind::Step;
		s.to_C = readNumber(node, "to_C", where);
	}
	else if (type == "sine")
	{
		checkKeys(node, {"type", "amplitude_C", "period_min", "cycles"}, where);
		s.kind = ProfileSegment::Kind::Sine;
		s.amplitude_C = readNumber(node, "amplitude_C", where);
		s.period_s = readPositive(node, "period_min", where) * kSecondsPerMinute;
		s.duration_s = s.period_s * readPositive(node, "cycles", where);
	}
	else if (type == "sweep")
	{
		checkKeys(node, {"type", "amplitude_C", "period_start_min", "period_end_min", "duration_min"}, where);
		s.kind = ProfileSegment::Kind::Sweep;
		s.amplitude_C = readNumber(node, "amplitude_C", where);
		s.period_s = readPositive(node, "period_start_min", where) * kSecondsPerMinute;
		s.period_end_s = readPositive(node, "period_end_min", where) * kSecondsPerMinute;
		s.duration_s = readPositive(node, "duration_min", where) * kSecondsPerMinute;
	}
	else if (type == "power")
	{
		checkKeys(node, {"type", "on"}, where);
		s.kind = ProfileSegment::Kind::Power;
		if (!node.has("on")) fieldError(where + ".on", "missing");
		s.value = readBool(node, "on", where, true) ? 1.0 : 0.0;
	}
	else if (type == "table")
	{
		checkKeys(node, {"type", "rate_dph"}, where);
		s.kind = ProfileSegment::Kind::Table;
		s.value = readNumber(node, "rate_dph", where);
	}
	else if (type == "field")
	{
		checkKeys(node, {"type", "field_uT"}, where);
		s.kind = ProfileSegment::Kind::Field;
		s.value = readNumber(node, "field_uT", where);
	}
	else
		fieldError(where + ".type",
				   type.empty() ? "missing"
								: "unknown segment type '" + type + "' (hold, ramp, step, sine, sweep, power, table, field)");
	return s;
}

// Phase [rad] of a log-swept sine whose period goes from P0 to P1 over duration T:
// f(t) = f0 * (f1/f0)^(t/T), phase = 2 pi f0 T (k^(t/T) - 1) / ln k, k = f1/f0.
double sweepPhase_rad(const ProfileSegment& s, double tau_s)
{
	const double f0 = 1.0 / s.period_s, f1 = 1.0 / s.period_end_s;
	const double k = f1 / f0;
	if (std::abs(k - 1.0) < 1e-12) return 2 * units::kPi * f0 * tau_s;
	return 2 * units::kPi * f0 * s.duration_s * (std::pow(k, tau_s / s.duration_s) - 1.0) / std::log(k);
}
}  // namespace

ChamberProfile ChamberProfile::fromYaml(const mrpt::containers::yaml& doc, const std::string& source)
{
	const std::string top = source + ":";
	checkKeys(doc, {"name", "initial_temp_C", "power_initially", "initial_state", "segments"}, top);
	ChamberProfile p;
	p.name_ = readString(doc, "name", top, "custom");
	p.initial_C_ = readNumber(doc, "initial_temp_C", top, 25.0);
	p.power_initially_ = readBool(doc, "power_initially", top, true);
	const std::string init = readString(doc, "initial_state", top, "steady");
	if (init == "steady")
		p.initial_state_ = InitialThermalState::Steady;
	else if (init == "cold")
		p.initial_state_ = InitialThermalState::Cold;
	else
		fieldError(top + " initial_state", "expected steady or cold, got '" + init + "'");
	if (!doc.has("segments") || !doc["segments"].isSequence() || doc["segments"].asSequence().empty())
		fieldError(top + " segments", "missing or empty list of segments");

	double t = 0, temp = p.initial_C_;
	const auto& seq = doc["segments"].asSequence();
	for (std::size_t i = 0; i < seq.size(); i++)
	{
		const std::string where = source + ": segments[" + std::to_string(i) + "]";
		ProfileSegment s = parseSegment(mrpt::containers::yaml(seq[i]), where);
		s.start_s = t;
		s.from_C = temp;
		if (s.kind == ProfileSegment::Kind::Ramp)
		{
			s.duration_s = std::abs(s.to_C - temp) / s.value * kSecondsPerMinute;
			temp = s.to_C;
		}
		else if (s.kind == ProfileSegment::Kind::Step)
			temp = s.to_C;
		else if (s.kind == ProfileSegment::Kind::Sine)
			temp = s.from_C + s.amplitude_C * std::sin(2 * units::kPi * s.duration_s / s.period_s);
		else if (s.kind == ProfileSegment::Kind::Sweep)
			temp = s.from_C + s.amplitude_C * std::sin(sweepPhase_rad(s, s.duration_s));
		t += s.duration_s;
		p.segments_.push_back(s);
	}
	p.duration_s_ = t;
	if (!(p.duration_s_ > 0)) fieldError(top + " segments", "total duration is zero (add a hold or ramp)");
	return p;
}

ChamberProfile ChamberProfile::fromFile(const std::string& path)
{
	return fromYaml(parseYamlFile(path), path);
}

std::vector<std::string> ChamberProfile::presetNames()
{
	std::vector<std::string> names;
	for (const auto& kv : presetTable()) names.push_back(kv.first);
	return names;
}

std::string ChamberProfile::presetYaml(const std::string& name)
{
	const auto it = presetTable().find(name);
	if (it == presetTable().end())
	{
		std::string list;
		for (const auto& n : presetNames()) list += (list.empty() ? "" : ", ") + n;
		throw std::invalid_argument("unknown profile preset '" + name + "' (built-in: " + list + ")");
	}
	return it->second;
}

ChamberProfile ChamberProfile::preset(const std::string& name)
{
	std::istringstream ss(presetYaml(name));
	return fromYaml(mrpt::containers::yaml::FromStream(ss), "preset " + name);
}

ChamberState ChamberProfile::stateAt(double t_s) const
{
	ChamberState st;
	st.air_C = initial_C_;
	st.power_on = power_initially_;
	for (const auto& s : segments_)
	{
		if (s.start_s > t_s) break;
		const double tau = std::min(t_s - s.start_s, s.duration_s);
		switch (s.kind)
		{
			case ProfileSegment::Kind::Hold: st.air_C = s.from_C; break;
			case ProfileSegment::Kind::Ramp:
				st.air_C = s.from_C + (s.to_C > s.from_C ? 1.0 : -1.0) * s.value * tau / kSecondsPerMinute;
				if (tau >= s.duration_s) st.air_C = s.to_C;
				break;
			case ProfileSegment::Kind::Step: st.air_C = s.to_C; break;
			case ProfileSegment::Kind::Sine:
				st.air_C = s.from_C + s.amplitude_C * std::sin(2 * units::kPi * tau / s.period_s);
				break;
			case ProfileSegment::Kind::Sweep: st.air_C = s.from_C + s.amplitude_C * std::sin(sweepPhase_rad(s, tau)); break;
			case ProfileSegment::Kind::Power: st.power_on = s.value != 0.0; break;
			case ProfileSegment::Kind::Table: st.table_rate_dph = s.value; break;
			case ProfileSegment::Kind::Field: st.field_uT = s.value; break;
		}
	}
	return st;
}

}  // namespace mrpt_fog::sim
