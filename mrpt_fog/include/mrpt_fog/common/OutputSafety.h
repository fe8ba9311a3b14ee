/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file OutputSafety.h
 * Checks a program runs on its file arguments BEFORE any work, so that no user file is lost
 * and no output is written in vain:
 *  - an output that is the same file as an input (or as another output) is refused: compared by
 *    device and inode for existing files (so hard links, symlinks and "./a" vs "a" are caught),
 *    by resolved path for outputs that do not exist yet;
 *  - an output whose directory is missing or not writable is refused (a `--json` into a missing
 *    directory fails before the main output is written). Existing non-regular outputs (devices
 *    such as /dev/null, FIFOs) need no directory: they are written directly.
 * Errors are std::invalid_argument naming the option and the path. */

#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog
{
/** A file argument: the option that gave it (e.g. "-o", "--json") and the path. Empty paths
 * (option not given) are ignored. */
struct FileArg
{
	std::string option;
	std::string path;
};

/** Throws std::invalid_argument when an output names the same file as an input or as another
 * output, or cannot be created (see the file comment). */
void requireSafeOutputs(const std::vector<FileArg>& inputs, const std::vector<FileArg>& outputs);

/** True when both paths name the same existing file (same device and inode). */
bool sameExistingFile(const std::string& a, const std::string& b);

}  // namespace mrpt_fog
