/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file GzFile.h
 * Whole-file reads and atomic writes of plain or gzip-compressed files through MRPT's
 * CFileGZInputStream / CFileGZOutputStream, with the integrity check MRPT does not do: a gzip
 * file whose trailer (CRC-32 and length) does not match the decompressed bytes was truncated
 * or corrupted, and reading it throws instead of returning a silently shortened content. */

#include <cstdint>
#include <string>

namespace mrpt_fog::io
{
/** True when the file starts with the gzip magic bytes (1f 8b). Throws FogIoError if the file
 * cannot be opened. */
bool isGzipFile(const std::string& path);

/** Entire decompressed content of `path` (plain files are read as they are; multi-member gzip
 * as written by pigz/bgzip is read member after member). Throws FogIoError naming the file
 * when it cannot be opened, or when it is gzip-compressed and truncated or corrupt (a member's
 * decompressed length or CRC-32 differ from its trailer). Streaming readers: io/GzStream.h. */
std::string readWholeFile(const std::string& path);

/** Writes `bytes` to `path` atomically (temporary file + rename), gzip-compressed when
 * `compress` is true. Throws FogIoError on failure; nothing is left under `path` then. */
void writeWholeFileAtomically(const std::string& path, const std::string& bytes, bool compress);

/** Standard CRC-32 (IEEE 802.3, as in gzip and zlib) of a byte block. */
uint32_t crc32Ieee(const void* data, std::size_t len, uint32_t crc = 0);

}  // namespace mrpt_fog::io
