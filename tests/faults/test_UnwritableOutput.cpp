/* mrpt_fog: fault injection: an output that cannot be written leaves the previous file intact. */
#include <gtest/gtest.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <unistd.h>

#include <algorithm>

#include "FaultRun.h"

using namespace mrpt_fog;

namespace
{
/** Files in a directory (names). */
std::vector<std::string> listing(const std::filesystem::path& dir)
{
	std::vector<std::string> out;
	for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path().filename().string());
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace

// The temporary file cannot be created (the output's name is so long that "<name>.tmp-XXXXXX"
// exceeds the file-name limit: ENAMETOOLONG, which even root gets): every writer throws naming
// the output, the previous file is byte-identical, and no other file appears. (Formerly
// this occupied the predictable "<name>.tmp-<pid>"; temporary names are now unpredictable.)
TEST(UnwritableOutput, TemporaryCannotBeCreatedPreviousFileIntact)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 100);
	const auto check = [&](const std::string& ext, const std::function<void(const std::string&)>& write) {
		const std::string name = std::string(250 - ext.size(), 'r') + ext;  // 250 bytes: fits NAME_MAX = 255
		const std::string out = dir.path(name);
		faulttest::writeBytes(out, "previous contents of " + ext + "\n");
		const auto before = listing(dir.dir());
		try
		{
			write(out);
			ADD_FAILURE() << ext << ": nothing thrown";
		}
		catch (const std::exception& e)
		{
			EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
		}
		EXPECT_EQ(faulttest::readBytes(out), "previous contents of " + ext + "\n");
		EXPECT_EQ(listing(dir.dir()), before);
	};
	check(".csv", [&](const std::string& p) { writeFogCsv(p, s); });
	check(".csv.gz", [&](const std::string& p) { writeFogCsv(p, s); });
	check(".rawlog", [&](const std::string& p) { writeFogRawlog(p, s); });
	check(".yaml", [&](const std::string& p) { saveCalibrationYaml(faulttest::calibration(), p); });
	check(".txt", [&](const std::string& p) { writeTextFileAtomically(p, "new"); });
}

// The rename fails (the output name is a non-empty directory): the temporary is removed, the
// directory and its content are untouched, the error names the output.
TEST(UnwritableOutput, RenameFailsNothingLeft)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 100);
	const std::string out = dir.path("out.csv");
	std::filesystem::create_directory(out);
	faulttest::writeBytes(out + "/keep.txt", "keep");
	const auto before = listing(dir.dir());
	const std::string e = faulttest::errorOf<std::runtime_error>([&] { writeFogCsv(out, s); });
	EXPECT_NE(e.find("out.csv"), std::string::npos) << e;
	EXPECT_EQ(listing(dir.dir()), before);
	EXPECT_EQ(faulttest::readBytes(out + "/keep.txt"), "keep");
}

// A directory that does not exist: clear error naming the output, nothing created.
TEST(UnwritableOutput, MissingDirectory)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 100);
	const std::string e = faulttest::errorOf<std::runtime_error>([&] { writeFogCsv(dir.path("no/such/dir/x.csv"), s); });
	EXPECT_NE(e.find("x.csv"), std::string::npos) << e;
	EXPECT_TRUE(listing(dir.dir()).empty());
}

// A directory without write permission (only meaningful when not running as root, who may write
// anyway: then skipped): error, previous file intact.
TEST(UnwritableOutput, ReadOnlyDirectory)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 100);
	if (::geteuid() == 0) GTEST_SKIP() << "running as root: permissions do not stop writes";
	const std::string out = dir.path("prev.csv");
	faulttest::writeBytes(out, "previous");
	std::filesystem::permissions(dir.dir(), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
	EXPECT_ANY_THROW(writeFogCsv(out, s));
	EXPECT_EQ(faulttest::readBytes(out), "previous");
}
