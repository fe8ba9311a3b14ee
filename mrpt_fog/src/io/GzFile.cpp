/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/GzFile.h>

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
/** Last 8 bytes of a gzip file: CRC-32 and uncompressed length mod 2^32 (little endian). */
void readGzipTrailer(const std::string& path, uint32_t& crc, uint32_t& isize, std::uint64_t& file_size)
{
	std::ifstream f(path, std::ios::binary | std::ios::ate);
	if (!f) throw FogIoError(path + ": cannot open: " + std::strerror(errno));
	file_size = static_cast<std::uint64_t>(f.tellg());
	if (file_size < 18) throw FogIoError(path + ": truncated gzip file (" + std::to_string(file_size) + " bytes)");
	unsigned char b[8];
	f.seekg(-8, std::ios::end);
	f.read(reinterpret_cast<char*>(b), 8);
	if (!f) throw FogIoError(path + ": cannot read the gzip trailer");
	crc = b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<uint32_t>(b[3]) << 24);
	isize = b[4] | (b[5] << 8) | (b[6] << 16) | (static_cast<uint32_t>(b[7]) << 24);
}
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
	const bool gz = isGzipFile(path);
	mrpt::io::CFileGZInputStream in;
	std::string why;
	if (!in.open(path, why)) throw FogIoError(path + ": cannot open: " + why);
	std::string bytes;
	std::vector<char> chunk(1 << 20);
	for (;;)
	{
		std::size_t got = 0;
		try
		{
			got = in.Read(chunk.data(), chunk.size());
		}
		catch (const std::exception& e)
		{
			throw FogIoError(path + ": corrupt or truncated gzip data after " + std::to_string(bytes.size()) +
							 " decompressed bytes");
		}
		if (got == 0) break;
		bytes.append(chunk.data(), got);
	}
	if (gz)
	{
		uint32_t crc = 0, isize = 0;
		std::uint64_t file_size = 0;
		readGzipTrailer(path, crc, isize, file_size);
		const uint32_t len32 = static_cast<uint32_t>(bytes.size() & 0xFFFFFFFFu);
		if (len32 != isize || crc32Ieee(bytes.data(), bytes.size()) != crc)
			throw FogIoError(path + ": truncated or corrupt gzip file (" + std::to_string(file_size) +
							 " compressed bytes gave " + std::to_string(bytes.size()) +
							 " bytes whose length/CRC-32 do not match the gzip trailer)");
	}
	return bytes;
}

void writeWholeFileAtomically(const std::string& path, const std::string& bytes, bool compress)
{
	try
	{
		writeFileAtomically(path, [&](const std::string& tmp) {
			if (compress)
			{
				mrpt::io::CFileGZOutputStream out;
				std::string why;
				if (!out.open(tmp, 6, why)) throw FogIoError(path + ": cannot create: " + why);
				if (!bytes.empty() && out.Write(bytes.data(), bytes.size()) != bytes.size())
					throw FogIoError(path + ": write error (disk full?)");
				out.close();
			}
			else
			{
				std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
				if (!f) throw FogIoError(path + ": cannot create " + tmp + ": " + std::strerror(errno));
				f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
				f.close();
				if (!f) throw FogIoError(path + ": write error (disk full?)");
			}
		});
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
