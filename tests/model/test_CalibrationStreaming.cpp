/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The fit and the figures over runs read in chunks from a temporary file (obs/FogRun.h)
 * give the same numbers, bit for bit, as over the same runs in memory. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/AxisRuns.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>

#include <cstring>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
/** The series copied row by row into a spilled FogRun (several chunks when it is long enough). */
FogRun spilled(const FogSeries& s)
{
	FogRun r(s, !s.table_rate_dph.empty(), !s.field_uT.empty(), !s.power.empty());
	for (std::size_t k = 0; k < s.size(); k++) r.append(s, k);
	return r;
}

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSameFigures(const FitFigures& a, const FitFigures& b)
{
	EXPECT_EQ(a.label, b.label);
	EXPECT_EQ(a.samples, b.samples);
	EXPECT_TRUE(same(a.rms_dph, b.rms_dph)) << a.rms_dph << " vs " << b.rms_dph;
	EXPECT_TRUE(same(a.stability_dph, b.stability_dph)) << a.stability_dph << " vs " << b.stability_dph;
	EXPECT_TRUE(same(a.range_dph, b.range_dph));
	EXPECT_TRUE(same(a.raw_stability_dph, b.raw_stability_dph));
	EXPECT_TRUE(same(a.raw_range_dph, b.raw_range_dph));
	EXPECT_EQ(a.temp_outside_samples, b.temp_outside_samples);
	EXPECT_EQ(a.rate_outside_samples, b.rate_outside_samples);
}

void expectSameCalibration(const Calibration& a, const Calibration& b)
{
	EXPECT_EQ(a.model.features.termNames(), b.model.features.termNames());
	ASSERT_EQ(a.model.coef_dph.size(), b.model.coef_dph.size());
	for (std::size_t i = 0; i < a.model.coef_dph.size(); i++)
		EXPECT_TRUE(same(a.model.coef_dph[i], b.model.coef_dph[i])) << i;
	EXPECT_TRUE(same(a.model.rms_held_out_dph, b.model.rms_held_out_dph));
	ASSERT_EQ(a.fallbacks.size(), b.fallbacks.size());
	for (std::size_t f = 0; f < a.fallbacks.size(); f++)
		for (std::size_t i = 0; i < a.fallbacks[f].coef_dph.size(); i++)
			EXPECT_TRUE(same(a.fallbacks[f].coef_dph[i], b.fallbacks[f].coef_dph[i]));
	EXPECT_EQ(a.rate_gaps, b.rate_gaps);
	EXPECT_TRUE(same(a.selection_stability.chosen_share, b.selection_stability.chosen_share));
	expectSameFigures(a.in_sample, b.in_sample);
	expectSameFigures(a.held_out, b.held_out);
}
}  // namespace

/** Runs A, B, A one after the other (about 74 000 samples at 1 Hz: three chunks spilled). */
FogSeries longRun(unsigned seed)
{
	FogSeries s = fogtest::makeCoilRun("A", seed);
	for (const char* p : {"B", "A"})
	{
		const FogSeries next = fogtest::makeCoilRun(p, seed + 1);
		const double t0 = s.time_s.back() + 1.0;
		for (std::size_t k = 0; k < next.size(); k++)
		{
			s.appendSampleFrom(next, k);
			s.time_s.back() += t0;
		}
	}
	return s;
}

// One run, regime folds, selection auto with its stability refits, spanning three chunks of the
// spilled form; with a gap longer than the rate window and a dropout stretch across a chunk
// boundary.
TEST(CalibrationStreaming, SpilledRunGivesTheSameCalibrationAndFigures)
{
	FogSeries s = longRun(3);
	ASSERT_GT(s.size(), 2 * FogRun::kChunkSamples);
	for (std::size_t k = FogRun::kChunkSamples; k < s.size(); k++) s.time_s[k] += 500.0;
	for (std::size_t k = FogRun::kChunkSamples - 50; k < FogRun::kChunkSamples + 50; k++) s.temp_C[1][k] = NAN;
	const FogRun run = spilled(s);
	EXPECT_EQ(run.inMemory(), nullptr);
	EXPECT_EQ(run.size(), s.size());
	const Calibration mem = fitCalibration(std::vector<FogSeries>{s}, "multipoint");
	std::vector<FogRun> runs;
	runs.push_back(spilled(s));
	const Calibration c = fitCalibrationRuns(runs, "multipoint");
	EXPECT_GE(c.rate_gaps, 1u);
	expectSameCalibration(mem, c);
	expectSameFigures(evaluateCalibration(mem, s, "v"), evaluateCalibration(mem, run, "v"));
}

// Two runs (leave-one-run-out), blocked folds and the non-causal estimator (which loads its runs).
TEST(CalibrationStreaming, SeveralRunsBlocksAndSavgolGiveTheSameCalibration)
{
	const FogSeries a = longRun(5), b = fogtest::makeCoilRun("B", 9);
	std::vector<FogRun> runs;
	runs.push_back(spilled(a));
	runs.push_back(spilled(b));
	const Calibration mem = fitCalibration(std::vector<FogSeries>{a, b}, "M3:Ti1,To1");
	expectSameCalibration(mem, fitCalibrationRuns(runs, "M3:Ti1,To1"));
	FitOptions o;
	o.fold_scheme = FoldScheme::Blocks;
	o.rate_estimator.kind = RateEstimatorKind::SavitzkyGolay;
	o.rate_estimator.poly_order = 2;
	std::vector<FogRun> one;
	one.push_back(spilled(a));
	expectSameCalibration(fitCalibration(std::vector<FogSeries>{a}, "M2:Ti1", o), fitCalibrationRuns(one, "M2:Ti1", o));
}

// runsForAxis() on spilled runs: the same runs kept and skipped, and each kept run's samples (one
// axis, the stated Earth rate subtracted where the gyro is on) equal the series form's.
TEST(CalibrationStreaming, AxisViewsEqualTheSeriesRunsForAxis)
{
	FogSeries a = fogtest::makeCoilRun("A", 11);
	a.has_axis = {{true, false, true}};
	a.rate_dph[0] = a.rate_dph[2];
	for (auto& r : a.rate_dph[0]) r = 0.5 * r - 3.0;
	a.power.assign(a.size(), 1.0);
	for (std::size_t k = 100; k < 200; k++) a.power[k] = 0.0;
	a.setMetadata("earth_rate_dph.x", "7.25");
	a.setMetadata("earth_rate_dph.z", "-1.5");
	FogSeries b = a;  // a rate-table run turning about z: left out for x
	b.table_rate_dph.assign(b.size(), 0.0);
	for (std::size_t k = 5000; k < 6000; k++) b.table_rate_dph[k] = 10.0;
	b.setMetadata("table_axis", "z");
	std::vector<FogRun> runs;
	runs.push_back(spilled(a));
	runs.push_back(spilled(b));
	for (GyroAxis ax : {GyroAxis::X, GyroAxis::Z})
	{
		std::vector<FogSeries> series{a, b};
		const AxisRunSet want = runsForAxis(series, {"a", "b"}, ax);
		const AxisRunViews got = runsForAxis(runs, {"a", "b"}, ax);
		EXPECT_EQ(want.labels, got.labels);
		EXPECT_EQ(want.skipped, got.skipped);
		EXPECT_EQ(want.earth_rate_removed, got.earth_rate_removed);
		ASSERT_EQ(want.runs.size(), got.runs.size());
		for (std::size_t r = 0; r < want.runs.size(); r++)
		{
			const FogSeries loaded = got.runs[r].load();
			EXPECT_EQ(loaded.has_axis, want.runs[r].has_axis);
			for (int x = 0; x < 3; x++)
			{
				ASSERT_EQ(loaded.rate_dph[x].size(), want.runs[r].rate_dph[x].size());
				for (std::size_t k = 0; k < loaded.rate_dph[x].size(); k++)
					ASSERT_TRUE(same(loaded.rate_dph[x][k], want.runs[r].rate_dph[x][k])) << x << " " << k;
			}
		}
	}
}
