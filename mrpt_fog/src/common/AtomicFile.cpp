/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/AtomicFile.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace mrpt_fog
{
void writeFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write)
{
	const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
	try
	{
		write(tmp);
	}
	catch (...)
	{
		std::remove(tmp.c_str());
		throw;
	}
	if (std::rename(tmp.c_str(), path.c_str()) != 0)
	{
		const std::string why = std::strerror(errno);
		std::remove(tmp.c_str());
		throw std::runtime_error("cannot write '" + path + "': " + why);
	}
}

void writeTextFileAtomically(const std::string& path, const std::string& text)
{
	writeFileAtomically(path, [&](const std::string& tmp) {
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f) throw std::runtime_error("cannot write '" + path + "': cannot create " + tmp + ": " + std::strerror(errno));
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
