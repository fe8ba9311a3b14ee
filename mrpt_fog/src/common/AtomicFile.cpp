/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <fcntl.h>
#include <limits.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/PathParts.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
// ---- Temporary files removed on SIGINT / SIGTERM / SIGHUP -------------------------------
// A fixed table the signal handler can walk without allocating: a slot is Free, being Filled
// (not yet visible to the handler) or Live (its path is complete).
constexpr int kSlots = 16;
enum SlotState : int
{
	Free = 0,
	Filling = 1,
	Live = 2
};
struct TempSlot
{
	std::atomic<int> state{Free};
	char path[PATH_MAX + 1];
};
TempSlot g_slots[kSlots];
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction g_previous[3];

extern "C" void removeTemporariesAndDie(int sig)
{
	for (auto& s : g_slots)
		if (s.state.load() == Live) ::unlink(s.path);
	// Then what would have happened without us: the previous handler, or death by the signal.
	for (int i = 0; i < 3; i++)
		if (kSignals[i] == sig)
		{
			const auto& prev = g_previous[i];
			if (!(prev.sa_flags & SA_SIGINFO) && prev.sa_handler != SIG_DFL && prev.sa_handler != SIG_IGN &&
				prev.sa_handler != removeTemporariesAndDie)
			{
				prev.sa_handler(sig);
				return;
			}
		}
	::signal(sig, SIG_DFL);
	::raise(sig);
}

void installSignalCleanup()
{
	static std::once_flag once;
	std::call_once(once, [] {
		for (int i = 0; i < 3; i++)
		{
			struct sigaction prev{};
			if (::sigaction(kSignals[i], nullptr, &prev) != 0) continue;
			if (!(prev.sa_flags & SA_SIGINFO) && prev.sa_handler == SIG_IGN) continue;  // e.g. nohup: keep ignoring
			g_previous[i] = prev;
			struct sigaction sa{};
			sa.sa_handler = removeTemporariesAndDie;
			sigemptyset(&sa.sa_mask);
			for (int s : kSignals) sigaddset(&sa.sa_mask, s);
			::sigaction(kSignals[i], &sa, nullptr);
		}
	});
}

/** Registers a temporary path for removal on a fatal signal; returns its slot (or -1 when the
 * table is full: the file is then only removed on exceptions). */
int registerTemporary(const std::string& path)
{
	installSignalCleanup();
	if (path.size() > PATH_MAX) return -1;
	for (int i = 0; i < kSlots; i++)
	{
		int expected = Free;
		if (g_slots[i].state.compare_exchange_strong(expected, Filling))
		{
			std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
			g_slots[i].state.store(Live);
			return i;
		}
	}
	return -1;
}

void unregisterTemporary(int slot)
{
	if (slot >= 0) g_slots[slot].state.store(Free);
}

/** The process umask now (a program may change it between two writes). Read from
 * /proc/self/status, which leaves it alone; where that is missing, set and restored at once. */
mode_t processUmask()
{
	std::ifstream status("/proc/self/status");
	std::string line;
	while (std::getline(status, line))
		if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8));
	const mode_t m = ::umask(022);
	::umask(m);
	return m;
}

std::string errnoText(int e) { return std::strerror(e); }

/** Where the bytes for `path` must go: the path itself, or a symlink's final target. */
std::string resolveOutput(const std::string& path)
{
	struct stat lst{};
	if (::lstat(path.c_str(), &lst) != 0 || !S_ISLNK(lst.st_mode)) return path;
	char buf[PATH_MAX + 1];
	if (::realpath(path.c_str(), buf) == nullptr)
		throw std::runtime_error("cannot write '" + path + "': it is a symlink whose target cannot be resolved (" +
								 errnoText(errno) + "); refusing to replace the link");
	return buf;
}

}  // namespace

int liveTemporaryFileCount()
{
	int n = 0;
	for (const auto& s : g_slots) n += s.state.load() != Free;
	return n;
}

AtomicOutput::AtomicOutput(const std::string& path) : path_(path)
{
	if (path.empty()) throw std::runtime_error("cannot write: empty output file name");
	target_ = resolveOutput(path);
	named_ = target_ == path ? "'" + path + "'" : "'" + path + "' (symlink to '" + target_ + "')";
	struct stat st{};
	const bool exists = ::stat(target_.c_str(), &st) == 0;
	if (exists && S_ISDIR(st.st_mode)) throw std::runtime_error("cannot write " + named_ + ": it is a directory");
	if (exists && !S_ISREG(st.st_mode))
	{
		// A device, FIFO or socket: write straight into it, never replace it.
		direct_ = true;
		write_path_ = target_;
		return;
	}
	std::string templ = target_ + ".tmp-XXXXXX";
	{
		// Block the cleanup signals while the name becomes visible and registered.
		sigset_t block, old;
		sigemptyset(&block);
		for (int s : kSignals) sigaddset(&block, s);
		installSignalCleanup();
		::sigprocmask(SIG_BLOCK, &block, &old);
		fd_ = ::mkostemp(templ.data(), O_CLOEXEC);
		const int err = errno;
		if (fd_ >= 0)
		{
			write_path_ = templ;
			slot_ = registerTemporary(templ);
		}
		::sigprocmask(SIG_SETMASK, &old, nullptr);
		if (fd_ < 0)
			throw std::runtime_error("cannot write " + named_ + ": cannot create a temporary file in '" + dirOf(target_) +
									 "': " + errnoText(err));
	}
	// The mode (and owner, where permitted) the output has, or would have as a new file.
	if (exists)
	{
		if (::fchown(fd_, st.st_uid, st.st_gid) != 0)
		{
			// Not permitted (not root): keep our own owner; the group alone may still be settable.
			(void)::fchown(fd_, static_cast<uid_t>(-1), st.st_gid);
		}
		::fchmod(fd_, st.st_mode & 07777);
	}
	else
		::fchmod(fd_, 0666 & ~processUmask());
}

AtomicOutput::~AtomicOutput()
{
	if (fd_ >= 0) ::close(fd_);
	if (!direct_ && !done_ && !write_path_.empty()) ::unlink(write_path_.c_str());
	unregisterTemporary(slot_);
}

void AtomicOutput::commit()
{
	if (done_) return;
	done_ = true;
	if (direct_) return;
	// The writer opened the temporary by name: check it is still the file we created.
	struct stat fst{}, nst{};
	if (::fstat(fd_, &fst) != 0 || ::lstat(write_path_.c_str(), &nst) != 0 || fst.st_dev != nst.st_dev ||
		fst.st_ino != nst.st_ino)
		throw std::runtime_error("cannot write " + named_ + ": the temporary file was replaced while being written");
	done_ = false;  // from here on, a failure removes the temporary
	if (::fsync(fd_) != 0)
		throw std::runtime_error("cannot write " + named_ + ": " + errnoText(errno) + " (while syncing to disk)");
	if (std::rename(write_path_.c_str(), target_.c_str()) != 0)
		throw std::runtime_error("cannot write " + named_ + ": " + errnoText(errno));
	done_ = true;
}

void writeFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write)
{
	AtomicOutput out(path);
	try
	{
		write(out.writePath());
	}
	catch (const std::exception& e)
	{
		const std::string what = e.what();
		if (what.find(path) != std::string::npos) throw;
		throw std::runtime_error("cannot write " + out.named() + ": " + what);
	}
	out.commit();
}

void writeTextFileAtomically(const std::string& path, const std::string& text)
{
	writeFileAtomically(path, [&](const std::string& tmp) {
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f) throw std::runtime_error("cannot write '" + path + "': cannot open: " + std::strerror(errno));
		f << text;
		f.close();
		if (!f) throw std::runtime_error("cannot write '" + path + "': write error (disk full?)");
	});
}

std::string fileExtension(const std::string& path)
{
	std::string p = path;
	std::transform(p.begin(), p.end(), p.begin(), [](unsigned char c) { return std::tolower(c); });
	const auto slash = p.find_last_of('/');
	const std::string base = slash == std::string::npos ? p : p.substr(slash + 1);
	std::string suffix;
	std::string stem = base;
	if (stem.size() > 3 && stem.compare(stem.size() - 3, 3, ".gz") == 0)
	{
		suffix = ".gz";
		stem = stem.substr(0, stem.size() - 3);
	}
	const auto dot = stem.find_last_of('.');
	if (dot == std::string::npos || dot == 0) return suffix;
	return stem.substr(dot) + suffix;
}

}  // namespace mrpt_fog
