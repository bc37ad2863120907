// Writes an output file so that readers never see it half written: the content goes to a
// temporary file in the same folder, which then replaces the target with one rename.
#pragma once
#include <functional>
#include <string>

namespace wf {

// Calls `writer` with a temporary path "<path>.tmp-<pid>" in the target's folder, then renames
// it over `path` (replacing an existing file). If `writer` throws, the temporary file is
// removed and the exception propagates.
// Throws InputError when the target's folder does not exist, InternalError when the rename
// fails.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writer);

} // namespace wf
