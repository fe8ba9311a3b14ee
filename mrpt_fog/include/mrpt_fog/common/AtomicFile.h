/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AtomicFile.h
 * Output files are never left half-written under the name the user asked for: everything is
 * written to a temporary sibling ("<path>.tmp-<pid>") and renamed over `path` only on success.
 * On failure (exception) the temporary file is removed and any previous file at `path` is intact.
 */

#include <functional>
#include <string>

namespace mrpt_fog
{
/** Calls write(tmp_path) and then renames tmp_path to path (atomic on POSIX filesystems).
 * If write throws, or the rename fails, tmp_path is deleted and a std::runtime_error naming
 * `path` is thrown; an existing file at `path` is left untouched. */
void writeFileAtomically(const std::string& path, const std::function<void(const std::string& tmp_path)>& write);

/** Writes `text` to `path` atomically (see writeFileAtomically). */
void writeTextFileAtomically(const std::string& path, const std::string& text);

/** Lower-case extension including the dot, with ".gz" folded in: "a.rawlog" -> ".rawlog",
 * "a.csv" -> ".csv", "a.csv.gz" -> ".csv.gz". Empty when none. */
std::string fileExtension(const std::string& path);

}  // namespace mrpt_fog
