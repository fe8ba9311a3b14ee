/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/GzFile.h>
#include <mrpt_fog/io/GzStream.h>

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

namespace mrpt_fog::io
{
namespace
{
}  // namespace

uint32_t crc32Ieee(const void* data, std::size_t len, uint32_t crc)
{
	// zlib's CRC-32 (the gzip one), fed in chunks its uInt length can hold.
	const auto* p = static_cast<const Bytef*>(data);
	uLong c = crc;
	while (len > 0)
	{
		const uInt n = static_cast<uInt>(std::min<std::size_t>(len, 1u << 30));
		c = ::crc32(c, p, n);
		p += n;
		len -= n;
	}
	return static_cast<uint32_t>(c);
}

bool isGzipFile(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	if (!f) throw FogIoError(path + ": cannot open: " + std::strerror(errno));
	unsigned char magic[2] = {0, 0};
	f.read(reinterpret_cast<char*>(magic), 2);
	return f.gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
}

std::string readWholeFile(const std::string& path)
{
	GzReader in(path);  // multi-member gzip; every member's CRC-32 and length checked
	std::string bytes;
	std::vector<char> chunk(1 << 20);
	for (;;)
	{
		const std::size_t got = in.Read(chunk.data(), chunk.size());
		if (got == 0) break;
		bytes.append(chunk.data(), got);
	}
	return bytes;
}

void writeWholeFileAtomically(const std::string& path, const std::string& bytes, bool compress)
{
	try
	{
		AtomicOutput out(path);
		GzWriter w(out.writePath(), compress, 6, path);
		w.write(bytes);
		w.close();
		out.commit();
	}
	catch (const FogIoError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		throw FogIoError(e.what());
	}
}

}  // namespace mrpt_fog::io
