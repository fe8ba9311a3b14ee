/* mrpt_fog: hostile calibration and profile YAML: deep nesting crashed MRPT's parser
 * (SIGSEGV, exit 139), huge texts cost ~90 bytes of memory per byte, aliases expand
 * exponentially, and absurd numbers (coef_dph 1e308, window_s 1e9) were accepted. Each case runs
 * in a child process (a crash must not take the test binary with it) and must end in
 * std::invalid_argument naming the file and the limit or field. */
#include <gtest/gtest.h>
#include <mrpt_fog/common/YamlGuard.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <functional>

#include "FaultRun.h"
#include "support/AddressSpaceLimit.h"

using namespace mrpt_fog;

namespace
{
/** Runs `load` in a child (20 s alarm, 2 GB address space). Returns "" when it threw
 * std::invalid_argument whose text holds every one of `expect`; else what happened. */
std::string refusedInChild(const std::function<void()>& load, const std::vector<std::string>& expect)
{
	int pipefd[2];
	if (::pipe(pipefd) != 0) return "pipe failed";
	const pid_t pid = ::fork();
	if (pid == 0)
	{
		::close(pipefd[0]);
		::alarm(20);
		fogtest::limitAddressSpace(2048ull << 20);  // not under ASan (support/AddressSpaceLimit.h)
		std::string msg;
		int code = 0;
		try
		{
			load();
			msg = "loaded without error";
			code = 1;
		}
		catch (const std::invalid_argument& e)
		{
			msg = e.what();
			for (const auto& x : expect)
				if (msg.find(x) == std::string::npos) code = 2;
		}
		catch (const std::exception& e)
		{
			msg = std::string("other exception: ") + e.what();
			code = 3;
		}
		if (::write(pipefd[1], msg.data(), msg.size()) < 0) code = 4;
		::_exit(code);
	}
	::close(pipefd[1]);
	std::string msg;
	char buf[4096];
	for (ssize_t n; (n = ::read(pipefd[0], buf, sizeof(buf))) > 0;) msg.append(buf, static_cast<std::size_t>(n));
	::close(pipefd[0]);
	int status = 0;
	::waitpid(pid, &status, 0);
	if (!WIFEXITED(status)) return "killed by signal " + std::to_string(WTERMSIG(status)) + " (crash or hang)";
	if (WEXITSTATUS(status) != 0) return "exit " + std::to_string(WEXITSTATUS(status)) + ": " + msg.substr(0, 300);
	return "";
}

std::string validCalibrationText() { return calibrationToYaml(faulttest::calibration()); }

/** The text with the first occurrence of `key: <value>` after `after` given another value. */
std::string withValue(std::string text, const std::string& key, const std::string& value, const std::string& after = "")
{
	const auto from = after.empty() ? 0 : text.find(after);
	const auto k = text.find(key + ": ", from);
	EXPECT_NE(k, std::string::npos) << key;
	const auto b = k + key.size() + 2;
	auto e = text.find_first_of(" \n", b);
	text.replace(b, e - b, value);
	return text;
}

void expectCalibrationRefused(const std::string& text, const std::vector<std::string>& expect)
{
	EXPECT_EQ(refusedInChild([&] { (void)calibrationFromYaml(text, "hostile.yaml"); }, expect), "")
		<< text.substr(0, 120);
}
}  // namespace

TEST(HostileYaml, DeepFlowNestingRefusedNotCrashed)
{
	expectCalibrationRefused(std::string(100000, '[') + std::string(100000, ']'), {"hostile.yaml", "nesting depth", "64"});
	expectCalibrationRefused("a: " + std::string(5000, '{'), {"hostile.yaml:1", "nesting depth"});
}

TEST(HostileYaml, DeepBlockNestingRefusedNotCrashed)
{
	std::string compact;
	for (int i = 0; i < 20000; i++) compact += "- ";
	expectCalibrationRefused(compact + "x\n", {"nesting depth"});
	std::string indented;
	for (int i = 0; i < 2000; i++) indented += std::string(static_cast<std::size_t>(i), ' ') + "k:\n";
	expectCalibrationRefused(indented, {"nesting depth"});
}

TEST(HostileYaml, HugeTextRefusedBeforeParsing)
{
	std::string huge = validCalibrationText();
	huge += "# " + std::string(20u << 20, 'x') + "\n";
	expectCalibrationRefused(huge, {"hostile.yaml", "exceeds the limit of 16777216 bytes"});
	// From a file: refused on its size before it is read.
	const std::string path = std::string(FOG_BINARY_DIR) + "/hostile_huge.yaml";
	{
		std::ofstream f(path, std::ios::binary);
		f << huge;
	}
	EXPECT_EQ(refusedInChild([&] { (void)loadCalibrationYaml(path); }, {"hostile_huge.yaml", "exceeds the limit"}), "");
	std::remove(path.c_str());
}

TEST(HostileYaml, AliasBombRefused)
{
	std::string bomb = "a: &a [x, x, x, x, x, x, x, x, x, x]\n";
	for (char c = 'b'; c <= 'k'; c++)
	{
		const char p = static_cast<char>(c - 1);
		bomb += std::string(1, c) + ": &" + c + " [*" + p + ", *" + p + ", *" + p + ", *" + p + ", *" + p + ", *" + p +
				", *" + p + ", *" + p + ", *" + p + ", *" + p + "]\n";
	}
	expectCalibrationRefused(bomb, {"hostile.yaml:2", "aliases"});
}

TEST(HostileYaml, AbsurdNumbersRefusedWithField)
{
	const std::string ok = validCalibrationText();
	ASSERT_NO_THROW((void)calibrationFromYaml(ok, "ok.yaml"));
	expectCalibrationRefused(withValue(ok, "coef_dph", "1e308", "terms:"), {"hostile.yaml", "model.terms[0].coef_dph", "1e+308"});
	expectCalibrationRefused(withValue(ok, "coef_dph", "-3e6", "terms:"), {"model.terms[0].coef_dph"});
	expectCalibrationRefused(withValue(ok, "coef_dph", ".inf", "terms:"), {"model.terms[0].coef_dph", "finite"});
	expectCalibrationRefused(withValue(ok, "window_s", "1e9"), {"rate_estimator", "3600"});
	expectCalibrationRefused(withValue(ok, "mean_bias_dph", "1e300"), {"mean_bias_dph"});
	expectCalibrationRefused(withValue(ok, "max", "1e9", "signals:"), {"model.signals[0].max"});
	expectCalibrationRefused(withValue(ok, "centre", ".nan", "signals:"), {"model.signals[0].centre"});
	// Integer fields (CI fuzzing found poly_order 1e300 converted to int: undefined behaviour).
	expectCalibrationRefused(withValue(ok, "poly_order", "1e300"), {"rate_estimator.poly_order", "outside"});
	expectCalibrationRefused(withValue(ok, "poly_order", "-1e19"), {"rate_estimator.poly_order", "outside"});
	expectCalibrationRefused(withValue(ok, "poly_order", "1.5"), {"rate_estimator.poly_order", "whole number"});
	expectCalibrationRefused(withValue(ok, "samples", "1e300"), {"samples", "outside"});
}

TEST(HostileYaml, ProfileFilesGuardedToo)
{
	const std::string path = std::string(FOG_BINARY_DIR) + "/hostile_profile.yaml";
	{
		std::ofstream f(path, std::ios::binary);
		f << "name: deep\nsegments: " << std::string(100000, '[') << "\n";
	}
	EXPECT_EQ(refusedInChild([&] { (void)sim::ChamberProfile::fromFile(path); }, {"hostile_profile.yaml", "nesting depth"}), "");
	std::remove(path.c_str());
}

// Ill-formed UTF-8 in a '%' directive line sends libfyaml into an endless loop (found by
// fuzz_calibration_yaml: a 38-byte file, killed at the 10 s timeout); refused before parsing.
TEST(HostileYaml, IllFormedUtf8InDirectiveRefusedNotHung)
{
	expectCalibrationRefused(std::string("%# mrr 0.m coef_allrange2\0\0\0_dph:\x1b-\xe0\x92\x96", 38), {"hostile.yaml", "not valid UTF-8", "byte offset 35"});
	expectCalibrationRefused("%x \xed\xa0\x80\n", {"not valid UTF-8", "byte offset 3"});  // surrogate
	expectCalibrationRefused("%x \xf4\x90\x80\x80\n", {"not valid UTF-8"});  // above U+10FFFF
}

// The guard does not refuse what this project writes.
TEST(HostileYaml, RealFilesPass)
{
	EXPECT_NO_THROW(requireSafeYamlText(validCalibrationText(), "cal.yaml"));
	EXPECT_NO_THROW(requireSafeYamlText(sim::ChamberProfile::presetYaml("seed"), "seed"));
	EXPECT_NO_THROW(requireSafeYamlText("a: 'it''s * fine'\nb: \"*[{\"\nc: x*y  # *[[[\n", "q.yaml"));
}
