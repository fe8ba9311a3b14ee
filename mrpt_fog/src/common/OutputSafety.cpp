/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <limits.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/common/PathParts.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
std::string describe(const FileArg& f) { return f.option + " '" + f.path + "'"; }

/** A key naming the file a path will be written to: "dev:ino" of an existing file, else the
 * resolved directory + name (symlinks followed). */
std::string identity(const std::string& path)
{
	struct stat st{};
	if (::stat(path.c_str(), &st) == 0)
		return "i" + std::to_string(static_cast<unsigned long long>(st.st_dev)) + ":" +
			   std::to_string(static_cast<unsigned long long>(st.st_ino));
	char buf[PATH_MAX + 1];
	const std::string dir = dirOf(path);
	if (::realpath(dir.c_str(), buf) == nullptr) return "p" + path;
	return "p" + std::string(buf) + "/" + baseOf(path);
}
}  // namespace

bool sameExistingFile(const std::string& a, const std::string& b)
{
	struct stat sa{}, sb{};
	return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
		   sa.st_ino == sb.st_ino;
}

void requireSafeOutputs(const std::vector<FileArg>& inputs, const std::vector<FileArg>& outputs)
{
	std::vector<std::pair<std::string, const FileArg*>> seen;  // identity of each regular output
	for (const auto& out : outputs)
	{
		if (out.path.empty()) continue;
		struct stat st{};
		const bool exists = ::stat(out.path.c_str(), &st) == 0;
		if (exists && S_ISDIR(st.st_mode))
			throw std::invalid_argument(describe(out) + ": is a directory, not a file");
		struct stat lst{};
		if (!exists && ::lstat(out.path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode))
			throw std::invalid_argument(describe(out) + ": is a symlink to a missing file (dangling); refusing to "
													  "replace the link");
		const bool special = exists && !S_ISREG(st.st_mode);  // device, FIFO: written directly
		for (const auto& in : inputs)
			if (!in.path.empty() && exists && sameExistingFile(in.path, out.path))
			{
				if (special) continue;  // e.g. -i /dev/stdin -o /dev/stdout on a terminal
				throw std::invalid_argument(describe(out) + " is the same file as the input " + describe(in) +
											": refusing to overwrite an input");
			}
		if (special) continue;
		const std::string id = identity(out.path);
		for (const auto& [other_id, other] : seen)
			if (other_id == id)
				throw std::invalid_argument(describe(out) + " is the same file as " + describe(*other) +
											": two outputs cannot share a file");
		seen.emplace_back(id, &out);
		// Where the file will be created: the directory of the symlink's target for a symlink.
		std::string target = out.path;
		char buf[PATH_MAX + 1];
		if (exists && ::realpath(out.path.c_str(), buf) != nullptr) target = buf;
		const std::string dir = dirOf(target);
		struct stat dst{};
		if (::stat(dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode))
			throw std::invalid_argument(describe(out) + ": directory '" + dir + "' does not exist");
		if (::access(dir.c_str(), W_OK | X_OK) != 0)
			throw std::invalid_argument(describe(out) + ": directory '" + dir + "' is not writable (" +
										std::strerror(errno) + ")");
	}
}

}  // namespace mrpt_fog
