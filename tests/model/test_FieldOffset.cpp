/* FieldOffset: the field_offset section fog-refine appends to a calibration file. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/FieldOffset.h>

#include <cmath>
#include <stdexcept>

using namespace mrpt_fog;

TEST(FieldOffset, RoundTripAndReplacement)
{
	FieldOffset f;
	f.offset_dph = 0.2513;
	f.sigma_dph = 0.0185;
	f.aging_dph_per_day = 1.0 / 365.25;
	f.aging_sigma_dph_per_day = 0.0005;
	f.reference_unix_s = 1722297600;
	f.revision = 2;
	f.previous = "cal \"r1\".yaml";
	f.logs = {"a.rawlog", "b.rawlog"};
	const std::string base = "format: \"mrpt_fog calibration\"\nversion: 2\n";
	const std::string once = withFieldOffset(base, f);
	ASSERT_EQ(once.rfind(base, 0), 0u);  // the calibration's text is kept as it was
	const auto back = fieldOffsetFromYaml(once, "cal.yaml");
	ASSERT_TRUE(back.has_value());
	EXPECT_EQ(back->offset_dph, f.offset_dph);  // %.17g: exact
	EXPECT_EQ(back->aging_dph_per_day, f.aging_dph_per_day);
	EXPECT_EQ(back->revision, 2);
	EXPECT_EQ(back->previous, f.previous);
	EXPECT_EQ(back->logs, f.logs);
	// a second refinement replaces the section, it does not stack a second one
	f.revision = 3;
	const std::string twice = withFieldOffset(once, f);
	EXPECT_EQ(twice.find("field_offset:"), twice.rfind("field_offset:"));
	EXPECT_EQ(fieldOffsetFromYaml(twice, "cal.yaml")->revision, 3);
	EXPECT_FALSE(fieldOffsetFromYaml(base, "cal.yaml").has_value());
}

// offset(t) = offset + trend x days since the reference; its sigma grows with the distance.
TEST(FieldOffset, OffsetAtADate)
{
	FieldOffset f;
	f.offset_dph = 0.25;
	f.sigma_dph = 0.01;
	f.aging_dph_per_day = 0.002;
	f.aging_sigma_dph_per_day = 0.0003;
	f.reference_unix_s = 1000;
	EXPECT_DOUBLE_EQ(f.offsetAt_dph(1000 + 30 * 86400.0), 0.25 + 0.06);
	EXPECT_DOUBLE_EQ(f.sigmaAt_dph(1000 + 40 * 86400.0), std::hypot(0.01, 0.012));
}

TEST(FieldOffset, MalformedSectionIsRefused)
{
	const std::string head = "format: x\nfield_offset:\n";
	EXPECT_THROW(fieldOffsetFromYaml(head + "  offset_dph: 0.1\n", "c.yaml"), std::invalid_argument);  // fields missing
	EXPECT_THROW(fieldOffsetFromYaml(head + "  offset_dph: .nan\n  sigma_dph: 0\n  aging_dph_per_day: 0\n"
											"  aging_sigma_dph_per_day: 0\n  reference_unix_s: 0\n  revision: 1\n",
										"c.yaml"),
				 std::invalid_argument);
	EXPECT_THROW(fieldOffsetFromYaml(head + "  offset_dph: 0\n  sigma_dph: -1\n  aging_dph_per_day: 0\n"
											"  aging_sigma_dph_per_day: 0\n  reference_unix_s: 0\n  revision: 1\n",
										"c.yaml"),
				 std::invalid_argument);
}
