/* mrpt_fog: fault injection: a thermistor sticks at a constant value (ThermistorHealth). */
#include <gtest/gtest.h>
#include <mrpt_fog/model/ThermistorHealth.h>

#include <algorithm>
#include <iostream>

#include "FaultRun.h"

using namespace mrpt_fog;

namespace
{
/** Thermistor i holds its reading of sample k0 for samples k0..k1-1. */
FogSeries stuckRun(std::size_t i, std::size_t k0, std::size_t k1)
{
	FogSeries s = faulttest::validationRun();
	for (std::size_t k = k0; k < k1; k++) s.temp_C[i][k] = s.temp_C[i][k0];
	return s;
}
}  // namespace

// No false alarm: the screening leaves every reading of clean simulated runs untouched (the
// short run and the built-in seed, B and rich chamber profiles, which include a 20 degC air step,
// a fast sine sweep and power cycles). Prints the fastest thermistor change seen, the margin to
// max_rate_C_per_s.
TEST(ThermistorStuck, CleanSimulatedRunsAreNotFlagged)
{
	std::vector<FogSeries> runs = {faulttest::validationRun()};
	for (const char* p : {"seed", "B", "rich"})
	{
		sim::SimSettings s;
		s.rate_hz = 1.0;
		runs.push_back(sim::simulateChamber(sim::ChamberProfile::preset(p), sim::FogDevice::defaultDevice(), s));
	}
	for (auto& r : runs)
	{
		double max_rate = 0;
		for (const auto& col : r.temp_C)
			for (std::size_t k = 1; k < col.size(); k++)
				max_rate = std::max(max_rate, std::abs(col[k] - col[k - 1]) / (r.time_s[k] - r.time_s[k - 1]));
		const FogSeries before = r;
		const ThermistorScreening sc = screenThermistors(r);
		std::cout << r.metadataValue("sim.profile") << ": " << r.size() << " samples, fastest thermistor change "
				  << max_rate << " degC/s, rejected " << sc.rejected_readings << "\n";
		EXPECT_EQ(sc.rejected_readings, 0u) << r.metadataValue("sim.profile");
		EXPECT_EQ(r.temp_C, before.temp_C);
	}
}

// Bound: a thermistor stuck for the middle third of the run is detected no later than
// stuck_window_s (60 s) after its peers have moved stuck_peer_change_C (1 degC) since it stuck,
// and from then on is a dropout until it moves again; compensated with the screening, the 100 s
// stability is no worse than 2x the clean 4-thermistor result (the dropout bound).
TEST(ThermistorStuck, StuckSensorDetectedAndTreatedAsDropout)
{
	const Calibration& cal = faulttest::calibration();
	const FogSeries& clean_run = faulttest::validationRun();
	const double s4 = faulttest::stability100_dph(compensate(cal, clean_run));
	const auto& used = cal.model.features.thermistors();
	// stick during the heating ramp, where the peers move 1 degC/min
	const std::size_t k0 = faulttest::sampleAt(clean_run, 3600.0), k1 = faulttest::sampleAt(clean_run, 5400.0);
	for (const std::string& name : used)
	{
		const int i = clean_run.thermistorIndex(name);
		ASSERT_GE(i, 0);
		FogSeries faulty = stuckRun(i, k0, k1);
		const double s_unscreened = faulttest::stability100_dph(compensate(cal, faulty));
		const ThermistorHealthSettings set;
		// The detector's interval (ThermistorHealth.h) starts where the sensor's constant run began:
		// the first reading of the run within stuck_tolerance_C of which it has stayed. That can be
		// before k0 when the real reading was already steady there (near a turnaround).
		std::size_t k_run = 0;
		double run_v = faulty.temp_C[i][0];
		for (std::size_t k = 1; k <= k0; k++)
			if (std::abs(faulty.temp_C[i][k] - run_v) > set.stuck_tolerance_C)
			{
				k_run = k;
				run_v = faulty.temp_C[i][k];
			}
		// when did a peer move stuck_peer_change_C from its value at the run's start?
		std::size_t k_move = k0;
		for (; k_move < k1; k_move++)
		{
			bool moved = false;
			for (std::size_t j = 0; j < faulty.thermistorCount(); j++)
				if (static_cast<int>(j) != i && std::abs(faulty.temp_C[j][k_move] - faulty.temp_C[j][k_run]) >= set.stuck_peer_change_C) moved = true;
			if (moved) break;
		}
		ThermistorHealth health(faulty.thermistorCount(), set);
		std::vector<double> row(faulty.thermistorCount());
		std::size_t k_detect = 0;
		for (std::size_t k = 0; k < faulty.size(); k++)
		{
			for (std::size_t j = 0; j < row.size(); j++) row[j] = faulty.temp_C[j][k];
			health.step(faulty.time_s[k], row.data());
			for (std::size_t j = 0; j < row.size(); j++) faulty.temp_C[j][k] = row[j];
			if (!k_detect && health.state(i) == ThermistorState::Stuck) k_detect = k;
			if (k >= k1 + 1) ASSERT_NE(health.state(i), ThermistorState::Stuck) << "not released at " << k;
			for (std::size_t j = 0; j < row.size(); j++)
				if (static_cast<int>(j) != i) ASSERT_EQ(health.state(j), ThermistorState::Ok) << j << " at " << k;
		}
		ASSERT_GT(k_detect, 0u) << name << " never detected";
		const double latency_s = faulty.time_s[k_detect] - faulty.time_s[k0];
		EXPECT_LE(faulty.time_s[k_detect], std::max(faulty.time_s[k_move], faulty.time_s[k_run] + set.stuck_window_s) + 1.0)
			<< name << " peers moved at " << faulty.time_s[k_move];
		EXPECT_EQ(health.counters(i).stuck_events, 1u);
		EXPECT_EQ(health.counters(i).stuck, k1 - k_detect) << name;
		const CompensatedSeries c = compensate(cal, faulty);
		const double s = faulttest::stability100_dph(c);
		std::cout << name << " stuck at t=" << faulty.time_s[k0] << " s for " << (k1 - k0) << " s: detected after "
				  << latency_s << " s; stability screened " << s << " deg/h (" << s / s4 << " x clean), unscreened "
				  << s_unscreened << " deg/h (" << s_unscreened / s4 << " x)\n";
		EXPECT_GE(c.counters.fallback_samples, k1 - k_detect);
		EXPECT_LE(s, 2.0 * s4) << name;
	}
}

// A sensor that is constant while every other one is constant too is not flagged (its value is
// right), and a constant single thermistor is never flagged.
TEST(ThermistorStuck, ConstantWithConstantPeersIsNotStuck)
{
	ThermistorHealth h(2);
	double row[2];
	for (int k = 0; k < 1000; k++)
	{
		row[0] = 25.0;
		row[1] = 25.5;
		EXPECT_FALSE(h.step(k, row));
	}
	ThermistorHealth one(1);
	for (int k = 0; k < 1000; k++)
	{
		row[0] = 25.0;
		EXPECT_FALSE(one.step(k, row));
	}
	// the same two sensors when the second one heats at 1 degC/min: the first is stuck once it has
	// been constant stuck_window_s (30 s) and the peer has moved stuck_peer_change_C (0.2 degC, 12 s)
	ThermistorHealth h2(2);
	int detected = -1;
	for (int k = 0; k < 1000; k++)
	{
		row[0] = 25.0;
		row[1] = 25.5 + k / 60.0;
		h2.step(k, row);
		if (detected < 0 && h2.state(0) == ThermistorState::Stuck) detected = k;
	}
	EXPECT_EQ(detected, 30);
	EXPECT_EQ(h2.state(1), ThermistorState::Ok);
}

TEST(ThermistorStuck, BadTimeAndSettingsThrow)
{
	ThermistorHealth h(1);
	double x = 20;
	h.step(1.0, &x);
	EXPECT_THROW(h.step(1.0, &x), std::invalid_argument);
	EXPECT_THROW(h.step(0.5, &x), std::invalid_argument);
	EXPECT_THROW(h.step(std::nan(""), &x), std::invalid_argument);
	ThermistorHealthSettings s;
	s.stuck_window_s = 0;
	EXPECT_THROW(ThermistorHealth(1, s), std::invalid_argument);
	s = {};
	s.stuck_peer_change_C = s.stuck_tolerance_C;
	EXPECT_THROW(ThermistorHealth(1, s), std::invalid_argument);
}
