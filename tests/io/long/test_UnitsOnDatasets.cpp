/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* Long test (label "long"): the unit checks give no warning on any bundled dataset (every FOG
 * label of every log in datasets/, read whole: a few seconds each). */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/UnitPlausibility.h>

#include <filesystem>

using namespace mrpt_fog;

TEST(UnitsOnDatasets, NoWarningOnAnyBundledLog)
{
	std::size_t logs = 0;
	for (const auto& e : std::filesystem::directory_iterator(std::string(FOG_SOURCE_DIR) + "/datasets"))
	{
		const std::string p = e.path().string();
		const bool rawlog = p.size() > 7 && p.compare(p.size() - 7, 7, ".rawlog") == 0;
		const bool csv = p.size() > 7 && p.compare(p.size() - 7, 7, ".csv.gz") == 0;
		if (!rawlog && !csv) continue;
		for (const std::string label : {"FOG", "FOG_IDEAL"})
		{
			if (label == "FOG_IDEAL" && p.find("drive") == std::string::npos) continue;
			std::vector<LogNotice> notices;
			LogReadOptions opt;
			opt.notice = [&](const LogNotice& n) { notices.push_back(n); };
			FogLogReader r(p, label, ReadLimits{}, nullptr, opt);
			FogSample x;
			while (r.next(x))
			{
			}
			for (const auto& n : notices) ADD_FAILURE() << p << " " << label << ": " << n.message;
			logs++;
		}
	}
	EXPECT_GE(logs, 12u);
}
