/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file GzStream.h
 * Streaming file I/O for logs of any length (memory does not grow with the file):
 *  - GzReader reads a plain or gzip-compressed file in chunks. Multi-member gzip (pigz, bgzip,
 *    `cat a.gz b.gz`) is read member after member; zlib checks every member's CRC-32 and length,
 *    and a file that ends inside a member is reported truncated. It is an mrpt::io::CStream, so
 *    MRPT's CArchive deserialises objects from it one at a time.
 *  - GzWriter writes a plain or gzip-compressed file in chunks; a write or close error keeps its
 *    reason (e.g. "No space left on device"), which MRPT's CFileGZOutputStream loses.
 * Errors throw FogIoError naming the file. */

#include <mrpt/io/CStream.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace mrpt_fog::io
{
class GzReader : public mrpt::io::CStream
{
   public:
	/** Opens `path` (gzip detected by its magic bytes, not by the name). Throws FogIoError. */
	explicit GzReader(const std::string& path);
	~GzReader() override;
	GzReader(const GzReader&) = delete;
	GzReader& operator=(const GzReader&) = delete;

	/** Up to `count` decompressed bytes; fewer only at the end of the data. Throws FogIoError on
	 * corrupt or truncated gzip data. */
	size_t Read(void* buffer, size_t count) override;
	/** The next decompressed bytes without consuming them: p points at them and the return value
	 * is how many are contiguous there, at least `want` (at most the buffer size, 256 KiB) unless
	 * the data ends first. Valid until the next call of any other member. */
	std::size_t peek(const unsigned char*& p, std::size_t want);
	/** Consumes n bytes returned by peek(). */
	void consume(std::size_t n);
	/** True when no decompressed byte is left. */
	bool atEnd();
	/** Next line without its '\n' (a trailing '\r' removed). False at the end of the data.
	 * A line longer than max_bytes throws FogIoError "<path>:<line>: line longer than the limit
	 * of <max_bytes> bytes". */
	bool readLine(std::string& line, std::size_t max_bytes);
	std::size_t lineNumber() const { return line_no_; }  //!< of the last line returned

	const std::string& path() const { return path_; }
	bool compressed() const { return gzip_; }
	std::uint64_t fileBytes() const { return file_bytes_; }  //!< size on disk (0 if unknown)
	std::uint64_t fileBytesRead() const { return file_read_; }  //!< compressed bytes consumed
	std::uint64_t position() const { return out_pos_; }  //!< decompressed bytes delivered

	// mrpt::io::CStream
	size_t Write(const void*, size_t) override;
	uint64_t Seek(int64_t, CStream::TSeekOrigin) override;
	uint64_t getTotalBytesCount() const override { return file_bytes_; }
	uint64_t getPosition() const override { return out_pos_; }

   private:
	bool fill();  // more decompressed bytes appended to the waiting ones; false at the end (or buffer full)
	std::string path_;
	std::FILE* f_ = nullptr;
	bool gzip_ = false;
	struct Inflater;
	std::unique_ptr<Inflater> z_;
	std::vector<unsigned char> in_, buf_;
	std::size_t in_len_ = 0, in_pos_ = 0;  // compressed input buffer
	std::size_t buf_len_ = 0, buf_pos_ = 0;  // decompressed bytes waiting
	bool file_eof_ = false, member_open_ = false;
	std::uint64_t file_bytes_ = 0, file_read_ = 0, out_pos_ = 0, members_ = 0;
	std::size_t line_no_ = 0;
};

class GzWriter : public mrpt::io::CStream
{
   public:
	/** Creates/truncates `path` (gzip-compressed at `level` 1..9 when compress). `name` is the
	 * file named in errors (the user's output name when `path` is a temporary). */
	GzWriter(const std::string& path, bool compress, int level = 6, const std::string& name = "");
	~GzWriter() override;
	GzWriter(const GzWriter&) = delete;
	GzWriter& operator=(const GzWriter&) = delete;

	/** Writes all `count` bytes or throws FogIoError with the reason. */
	size_t Write(const void* buffer, size_t count) override;
	void write(const std::string& s) { Write(s.data(), s.size()); }
	/** Flushes and closes; throws FogIoError with the reason (e.g. disk full). */
	void close();

	// mrpt::io::CStream
	size_t Read(void*, size_t) override;
	uint64_t Seek(int64_t, CStream::TSeekOrigin) override;
	uint64_t getTotalBytesCount() const override { return in_bytes_; }
	uint64_t getPosition() const override { return in_bytes_; }

   private:
	void flushBuffer(bool finish);
	void writeRaw(const unsigned char* p, std::size_t n);
	[[noreturn]] void fail(const std::string& what, int err);
	std::string path_, name_;
	std::FILE* f_ = nullptr;
	bool compress_ = false, closed_ = false;
	struct Deflater;
	std::unique_ptr<Deflater> z_;
	std::vector<unsigned char> buf_, out_;
	std::size_t buf_len_ = 0;
	std::uint64_t in_bytes_ = 0;
};

}  // namespace mrpt_fog::io
