/* Tests of atomic output: on failure the previous file stays intact and no temp file remains. */
#include <gtest/gtest.h>
#include <mrpt_fog/common/AtomicFile.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

using namespace mrpt_fog;
namespace fs = std::filesystem;

namespace
{
std::string slurp(const fs::path& p)
{
	std::ifstream f(p);
	std::stringstream s;
	s << f.rdbuf();
	return s.str();
}
}  // namespace

TEST(AtomicFile, FailedWriteKeepsPreviousFile)
{
	const fs::path dir = fs::temp_directory_path() / ("fog_atomic_" + std::to_string(::getpid()));
	fs::create_directories(dir);
	const auto target = (dir / "out.txt").string();
	writeTextFileAtomically(target, "old contents\n");
	EXPECT_THROW(writeFileAtomically(target,
									 [](const std::string& tmp) {
										 std::ofstream(tmp) << "partial";
										 throw std::runtime_error("simulated failure");
									 }),
				 std::runtime_error);
	EXPECT_EQ(slurp(target), "old contents\n");
	std::size_t files = 0;
	for (const auto& e : fs::directory_iterator(dir))
	{
		(void)e;
		files++;
	}
	EXPECT_EQ(files, 1u) << "temporary file left behind";
	fs::remove_all(dir);
}

TEST(AtomicFile, UnwritableDirectoryGivesClearError)
{
	try
	{
		writeTextFileAtomically("/nonexistent_dir_fog/out.txt", "x");
		FAIL() << "expected an exception";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent_dir_fog/out.txt"), std::string::npos) << e.what();
	}
}

TEST(AtomicFile, ExtensionFoldsGz)
{
	EXPECT_EQ(fileExtension("/a/b/run.RAWLOG"), ".rawlog");
	EXPECT_EQ(fileExtension("run.csv.gz"), ".csv.gz");
	EXPECT_EQ(fileExtension("dir.v2/run"), "");
}
