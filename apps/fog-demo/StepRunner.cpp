/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "StepRunner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

extern char** environ;

namespace mrpt_fog::demo
{
namespace
{
std::string shellQuote(const std::string& s)
{
	if (s.find_first_of(" \t'\"$\\;&|<>()*?") == std::string::npos) return s;
	std::string q = "'";
	for (char c : s)
		if (c == '\'') q += "'\\''";
		else q += c;
	return q + "'";
}

std::string lastLine(const std::string& path)
{
	std::ifstream f(path);
	std::string line, last;
	while (std::getline(f, line))
		if (!line.empty()) last = line;
	return last;
}
}  // namespace

std::string executableDir()
{
	std::error_code ec;
	const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
	if (ec) throw std::runtime_error("cannot locate the fog-demo executable (/proc/self/exe)");
	return p.parent_path().string();
}

StepRunner::StepRunner(std::string bin_dir, std::string log_dir, int total_steps)
	: bin_dir_(std::move(bin_dir)), log_dir_(std::move(log_dir)), total_(total_steps)
{
	std::filesystem::create_directories(log_dir_);
}

std::string StepRunner::program(const std::string& name) const
{
	// Build tree: apps/<name>/<name>... CMake puts every app in build/apps/.
	const std::filesystem::path here(bin_dir_);
	for (const auto& cand : {here / name, here.parent_path() / name / name})
		if (std::filesystem::exists(cand)) return cand.string();
	throw std::runtime_error("program '" + name + "' not found next to fog-demo (" + bin_dir_ +
							 "); build it: cmake --build build --target " + name);
}

void StepRunner::run(const Step& step)
{
	done_++;
	std::cout << "[" << done_ << "/" << total_ << "] " << step.what << " ..." << std::flush;
	const auto t0 = std::chrono::steady_clock::now();
	const std::string log = log_dir_ + "/" + step.name + ".log";

	std::string cmd;
	for (const auto& a : step.argv) cmd += (cmd.empty() ? "" : " ") + shellQuote(a);
	commands_.push_back(cmd);

	std::vector<char*> args;
	for (const auto& a : step.argv) args.push_back(const_cast<char*>(a.c_str()));
	args.push_back(nullptr);
	posix_spawn_file_actions_t fa;
	posix_spawn_file_actions_init(&fa);
	posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
	pid_t pid = 0;
	const int rc = posix_spawn(&pid, args[0], &fa, nullptr, args.data(), environ);
	posix_spawn_file_actions_destroy(&fa);
	if (rc != 0) throw std::runtime_error("step '" + step.name + "': cannot start " + step.argv[0]);
	int status = 0;
	waitpid(pid, &status, 0);
	const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
	{
		std::cout << " FAILED\n";
		throw std::runtime_error("step '" + step.name + "' failed (" + lastLine(log) + "); full log: " + log);
	}
	char buf[64];
	std::snprintf(buf, sizeof(buf), " done (%.1f s)\n", secs);
	std::cout << buf << std::flush;
}

}  // namespace mrpt_fog::demo
