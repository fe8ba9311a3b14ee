/* Files are sacred: attacks on the output path (planted symlinks at the temporary name, outputs
 * that are symlinks, FIFOs or directories, modes, signals, outputs equal to inputs) and what the
 * writers and the programs' pre-checks must do about them. Each test failed before the fix
 * (predictable "<out>.tmp-<pid>" opened through symlinks, rename over anything). */
#include <fcntl.h>
#include <gtest/gtest.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

using namespace mrpt_fog;
namespace fs = std::filesystem;

namespace
{
class Scratch
{
   public:
	Scratch()
	{
		const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
		dir_ = fs::temp_directory_path() / ("fog_outsafe_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
		fs::remove_all(dir_);
		fs::create_directories(dir_);
	}
	~Scratch()
	{
		std::error_code ec;
		fs::remove_all(dir_, ec);
	}
	std::string path(const std::string& n) const { return (dir_ / n).string(); }
	std::vector<std::string> listing() const
	{
		std::vector<std::string> v;
		for (const auto& e : fs::directory_iterator(dir_)) v.push_back(e.path().filename().string());
		std::sort(v.begin(), v.end());
		return v;
	}

   private:
	fs::path dir_;
};

std::string slurp(const std::string& p)
{
	std::ifstream f(p, std::ios::binary);
	std::stringstream s;
	s << f.rdbuf();
	return s.str();
}
void put(const std::string& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
}  // namespace

// The old temporary name was "<out>.tmp-<pid>", opened through symlinks: a link planted there
// made the program overwrite the link's target. Now the temporary is created exclusively with an
// unpredictable name: the victim and the planted link are untouched.
TEST(OutputFileSafety, PlantedSymlinkAtOldTemporaryNameIsNotFollowed)
{
	Scratch d;
	const std::string victim = d.path("victim.txt"), out = d.path("out.json");
	put(victim, "precious\n");
	fs::create_symlink(victim, out + ".tmp-" + std::to_string(::getpid()));
	writeTextFileAtomically(out, "{}\n");
	EXPECT_EQ(slurp(victim), "precious\n");
	EXPECT_EQ(slurp(out), "{}\n");
	EXPECT_TRUE(fs::is_symlink(out + ".tmp-" + std::to_string(::getpid())));
	EXPECT_EQ(d.listing().size(), 3u);  // victim, link, output: no temporary left
}

TEST(OutputFileSafety, ExistingModeIsKept)
{
	Scratch d;
	const std::string out = d.path("cal.yaml");
	put(out, "old\n");
	::chmod(out.c_str(), 0600);
	writeTextFileAtomically(out, "new\n");
	struct stat st{};
	ASSERT_EQ(::stat(out.c_str(), &st), 0);
	EXPECT_EQ(st.st_mode & 07777, 0600u);
	::chmod(out.c_str(), 0640);
	writeTextFileAtomically(out, "newer\n");
	ASSERT_EQ(::stat(out.c_str(), &st), 0);
	EXPECT_EQ(st.st_mode & 07777, 0640u);
	EXPECT_EQ(slurp(out), "newer\n");
}

TEST(OutputFileSafety, NewFileGetsUmaskMode)
{
	Scratch d;
	const mode_t old = ::umask(027);
	writeTextFileAtomically(d.path("new.txt"), "x");
	::umask(old);
	struct stat st{};
	ASSERT_EQ(::stat(d.path("new.txt").c_str(), &st), 0);
	EXPECT_EQ(st.st_mode & 07777, 0640u);
}

// An output that is a symlink is written through to its target: the link stays a link.
TEST(OutputFileSafety, SymlinkOutputIsWrittenThrough)
{
	Scratch d;
	fs::create_directories(d.path("real"));
	const std::string target = d.path("real/data.csv"), link = d.path("link.csv");
	put(target, "old\n");
	fs::create_symlink(target, link);
	writeTextFileAtomically(link, "new\n");
	EXPECT_TRUE(fs::is_symlink(link));
	EXPECT_EQ(slurp(target), "new\n");
	EXPECT_EQ(d.listing(), (std::vector<std::string>{"link.csv", "real"}));
	// A dangling symlink is refused (where would the file go?), and left as it is.
	const std::string dangling = d.path("dangling.csv");
	fs::create_symlink(d.path("nowhere/x.csv"), dangling);
	EXPECT_THROW(writeTextFileAtomically(dangling, "x"), std::runtime_error);
	EXPECT_TRUE(fs::is_symlink(dangling));
}

// A FIFO is written into, never replaced: the same path as any non-regular output (/dev/null,
// /dev/stdout; not tested on /dev/null itself: a regression run as root would replace it).
TEST(OutputFileSafety, FifoOutputIsWrittenDirectly)
{
	Scratch d;
	const std::string fifo = d.path("pipe");
	ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
	std::string got;
	std::thread reader([&] { got = slurp(fifo); });
	writeTextFileAtomically(fifo, "through the pipe\n");
	reader.join();
	EXPECT_EQ(got, "through the pipe\n");
	struct stat st{};
	ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
	EXPECT_TRUE(S_ISFIFO(st.st_mode));
	EXPECT_EQ(d.listing(), (std::vector<std::string>{"pipe"}));
}

TEST(OutputFileSafety, DirectoryOutputRefused)
{
	Scratch d;
	fs::create_directories(d.path("out.json"));
	put(d.path("out.json/keep"), "k");
	EXPECT_THROW(writeTextFileAtomically(d.path("out.json"), "x"), std::runtime_error);
	EXPECT_EQ(slurp(d.path("out.json/keep")), "k");
	EXPECT_EQ(d.listing(), (std::vector<std::string>{"out.json"}));
}

// SIGTERM / SIGINT while the temporary is being written: it is removed, the previous output
// is intact and the process still dies of the signal.
TEST(OutputFileSafety, SignalRemovesTemporary)
{
	for (int sig : {SIGTERM, SIGINT})
	{
		Scratch d;
		const std::string out = d.path("big.rawlog");
		put(out, "previous\n");
		const pid_t child = ::fork();
		ASSERT_GE(child, 0);
		if (child == 0)
		{
			writeFileAtomically(out, [&](const std::string& tmp) {
				std::ofstream f(tmp, std::ios::binary);
				f << std::string(1 << 20, 'x');
				f.flush();
				::raise(sig);
			});
			::_exit(0);  // not reached
		}
		int status = 0;
		ASSERT_EQ(::waitpid(child, &status, 0), child);
		EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "status " << status;
		EXPECT_EQ(slurp(out), "previous\n");
		EXPECT_EQ(d.listing(), (std::vector<std::string>{"big.rawlog"}));
	}
}

TEST(OutputFileSafety, FailedWriteLeavesNoTemporary)
{
	Scratch d;
	EXPECT_THROW(writeFileAtomically(d.path("x.txt"),
									 [](const std::string& tmp) {
										 put(tmp, "partial");
										 throw std::runtime_error("simulated");
									 }),
				 std::runtime_error);
	EXPECT_TRUE(d.listing().empty());
	EXPECT_EQ(liveTemporaryFileCount(), 0);
}

// ---- requireSafeOutputs: the programs' check before any work

TEST(OutputFileSafety, OutputEqualToInputRefused)
{
	Scratch d;
	const std::string run = d.path("run.csv");
	put(run, "time_s,rate_z_dph\n0,1\n");
	EXPECT_THROW(requireSafeOutputs({{"-i", run}}, {{"-o", run}}), std::invalid_argument);
	// Other spellings of the same file: ./, a hard link, a symlink.
	const std::string dotted = d.path(".") + "/run.csv";
	EXPECT_THROW(requireSafeOutputs({{"-i", run}}, {{"-o", dotted}}), std::invalid_argument);
	fs::create_hard_link(run, d.path("hard.csv"));
	EXPECT_THROW(requireSafeOutputs({{"-i", run}}, {{"--json", d.path("hard.csv")}}), std::invalid_argument);
	fs::create_symlink(run, d.path("soft.csv"));
	try
	{
		requireSafeOutputs({{"--cal", run}}, {{"--json", d.path("soft.csv")}});
		FAIL() << "not refused";
	}
	catch (const std::invalid_argument& e)
	{
		const std::string m = e.what();
		EXPECT_NE(m.find("--json"), std::string::npos) << m;
		EXPECT_NE(m.find("--cal"), std::string::npos) << m;
	}
	EXPECT_NO_THROW(requireSafeOutputs({{"-i", run}}, {{"-o", d.path("other.csv")}, {"--json", ""}}));
}

TEST(OutputFileSafety, TwoOutputsSameFileRefused)
{
	Scratch d;
	EXPECT_THROW(requireSafeOutputs({}, {{"-o", d.path("a.yaml")}, {"--json", d.path(".") + "/a.yaml"}}),
				 std::invalid_argument);
	put(d.path("b.json"), "{}");
	EXPECT_THROW(requireSafeOutputs({}, {{"-o", d.path("b.json")}, {"--json", d.path("b.json")}}),
				 std::invalid_argument);
	// Devices may be shared: -o /dev/null --json /dev/null is fine.
	EXPECT_NO_THROW(requireSafeOutputs({}, {{"-o", "/dev/null"}, {"--json", "/dev/null"}}));
}

TEST(OutputFileSafety, MissingOutputDirectoryRefusedBeforeWork)
{
	Scratch d;
	try
	{
		requireSafeOutputs({}, {{"-o", d.path("cal.yaml")}, {"--json", d.path("no/such/dir/fit.json")}});
		FAIL() << "not refused";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("--json"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
	}
	EXPECT_THROW(requireSafeOutputs({}, {{"-o", d.path(".")}}), std::invalid_argument);  // a directory
}
