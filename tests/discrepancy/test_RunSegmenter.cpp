/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/RunSegmenter.h>
#include "support/SyntheticChamberRun.h"

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
const Segment& segmentAt(const std::vector<Segment>& segs, double t_s)
{
	for (const auto& s : segs)
		if (t_s >= s.t_start_s && t_s < s.t_end_s) return s;
	throw std::runtime_error("no segment at t");
}
}  // namespace

TEST(RunSegmenter, LabelsTheRichProfileFromTheData)
{
	// the synthetic all_conditions profile (SyntheticChamberRun.cpp, minutes): 0-30 hold 25 C (power-on),
	// 30-95 ramp to -40, 140 step to -20, 200-220 table, 280-360 ramp 60 -> 20, 460-475 field,
	// 510-530 power off, 530 power on
	const auto sig = computeRunSignals(makeSyntheticChamberRun(10).series);
	const auto segs = segmentRun(sig);
	const double min = 60;
	// the run starts powered: when the gyro was switched on is not in the data, so its first
	// 30 min are a soak, not a power-on transient (only the turn-on at 530 min is one)
	EXPECT_EQ(segmentAt(segs, 10 * min).type, SegmentType::Soak);
	EXPECT_EQ(segmentAt(segs, 70 * min).type, SegmentType::RampDown);
	EXPECT_EQ(segmentAt(segs, 70 * min).direction, TemperatureDirection::Cooling);
	EXPECT_EQ(segmentAt(segs, 143 * min).type, SegmentType::Step);
	EXPECT_EQ(segmentAt(segs, 143 * min).direction, TemperatureDirection::Heating);
	EXPECT_EQ(segmentAt(segs, 205 * min).type, SegmentType::RateTable);
	EXPECT_EQ(segmentAt(segs, 320 * min).type, SegmentType::RampDown);
	EXPECT_EQ(segmentAt(segs, 465 * min).type, SegmentType::Field);
	EXPECT_EQ(segmentAt(segs, 520 * min).type, SegmentType::PowerOff);
	EXPECT_EQ(segmentAt(segs, 535 * min).type, SegmentType::PowerOn);
	EXPECT_EQ(segmentAt(segs, 120 * min).band, "below -20 C");
	// cut at band edges: every segment's mean temperature lies in its band (0.1 C slack for
	// the derivative-window smoothing at the edges)
	for (const auto& s : segs)
		for (std::size_t k = s.begin; k < s.end; ++k)
		{
			if (!sig.usable[k] || s.band == "unknown band") continue;
			const double T = sig.temp_mean_C[k];
			if (s.band == "below -20 C") EXPECT_LT(T, -20.0 + 1e-9);
			if (s.band == "above 40 C") EXPECT_GE(T, 40.0 - 1e-9);
		}
	// the "ramp" profile: 1 C/min ramp 25 -> -40 C ending at 85 min, then a 2 h soak
	SyntheticRunOptions o;
	o.dt_s = 10;
	o.profile = SyntheticProfile::Ramp;
	const auto ramp = makeSyntheticChamberRun(o);
	const auto rsig = computeRunSignals(ramp.series);
	const auto rsegs = segmentRun(rsig);
	EXPECT_EQ(segmentAt(rsegs, 50 * min).type, SegmentType::RampDown);
	EXPECT_EQ(segmentAt(rsegs, 180 * min).type, SegmentType::Soak);
	EXPECT_EQ(segmentAt(rsegs, 180 * min).band, "below -20 C");
	EXPECT_EQ(segmentAt(rsegs, 180 * min).direction, TemperatureDirection::Steady);
	// segments tile the run
	EXPECT_EQ(segs.front().begin, 0u);
	for (std::size_t i = 1; i < segs.size(); ++i) EXPECT_EQ(segs[i].begin, segs[i - 1].end);
	EXPECT_EQ(segs.back().end, sig.size());
}

TEST(RunSegmenter, RankingSaysWhereTheResidualIs)
{
	const auto sig = computeRunSignals(makeSyntheticChamberRun(10).series);
	const auto segs = segmentRun(sig);
	Eigen::VectorXd r = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(sig.size()), 0.01);
	for (const auto& s : segs)
		if (s.type == SegmentType::RampDown && s.band == "below -20 C")
			for (std::size_t k = s.begin; k < s.end; ++k) r(static_cast<Eigen::Index>(k)) = 0.2;
	const auto rank = rankSegments(segs, r, sig.usable);
	EXPECT_NE(rank.sentence.find("cooling ramps below -20 C"), std::string::npos) << rank.sentence;
	EXPECT_EQ(rank.ranked.front().type, SegmentType::RampDown);
	double shares = 0;
	for (const auto& s : rank.ranked) shares += s.energy_share;
	EXPECT_NEAR(shares, 1.0, 1e-9);
	EXPECT_EQ(std::string(toString(SegmentType::RateTable)), "rate_table");
}
