/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AtomicFile.h
 * Output files are never left half-written under the name the user asked for, and a user's
 * file is never destroyed by accident:
 *  - a regular output (new or existing) is written to a temporary sibling created exclusively
 *    (mkstemp: unpredictable name "<path>.tmp-XXXXXX", O_EXCL so a planted symlink or file is
 *    never opened), which gets the existing output's mode (and owner, where permitted; else the
 *    mode a new file would have under the umask), is synced and then renamed over `path` only
 *    on success. On failure (exception), or when the program is stopped by SIGINT/SIGTERM/
 *    SIGHUP while writing, the temporary is removed and a previous file at `path` is intact.
 *  - an output that is a symlink is written THROUGH to its target (the link is kept; the
 *    target is replaced atomically in its own directory); a dangling symlink is refused.
 *  - an output that exists and is not a regular file (character/block device such as
 *    /dev/null or /dev/stdout, FIFO, socket) is written directly, never replaced.
 *  - a directory is refused.
 */

#include <functional>
#include <string>

namespace mrpt_fog
{
/** The same safe output as a scoped object, for writers that stream (write as they go):
 *
 *   AtomicOutput out(path);            // temporary created (or the FIFO/device itself)
 *   write everything to out.writePath();
 *   out.commit();                      // renamed over path; without commit() the destructor
 *                                      // removes the temporary (exception, early return)
 */
class AtomicOutput
{
   public:
	explicit AtomicOutput(const std::string& path);
	~AtomicOutput();
	AtomicOutput(const AtomicOutput&) = delete;
	AtomicOutput& operator=(const AtomicOutput&) = delete;

	/** Where to write: the temporary, or the output itself when it is not a regular file. */
	const std::string& writePath() const { return write_path_; }
	/** The output as named in errors ("'out.csv'" or "'link' (symlink to 'target')"). */
	const std::string& named() const { return named_; }
	/** Checks, syncs and renames the temporary over the output. Throws std::runtime_error. */
	void commit();

   private:
	std::string path_, target_, named_, write_path_;
	int fd_ = -1;
	int slot_ = -1;
	bool direct_ = false, done_ = false;
};

/** Calls write(tmp_path) and then renames tmp_path to path (atomic on POSIX filesystems); see
 * the file comment for symlinks and non-regular outputs (write() then receives the output path
 * itself). If write throws, or the rename fails, tmp_path is deleted and a std::runtime_error
 * naming `path` is thrown; an existing file at `path` is left untouched. */
void writeFileAtomically(const std::string& path, const std::function<void(const std::string& tmp_path)>& write);

/** Writes `text` to `path` atomically (see writeFileAtomically). */
void writeTextFileAtomically(const std::string& path, const std::string& text);

/** Lower-case extension including the dot, with ".gz" folded in: "a.rawlog" -> ".rawlog",
 * "a.csv" -> ".csv", "a.csv.gz" -> ".csv.gz". Empty when none. */
std::string fileExtension(const std::string& path);

/** How many temporary output files are open right now (tests: none may be left behind). */
int liveTemporaryFileCount();

}  // namespace mrpt_fog
