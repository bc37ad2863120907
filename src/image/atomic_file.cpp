// Same-folder temp file + rename: rename(2) is atomic only within one file system, and the
// target's own folder is the one place guaranteed to be on the same file system as the target.
#include "image/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "errors.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

// Flushes the temp file's data to disk before the rename, so a crash right after the rename
// cannot leave an empty file under the final name. Best effort: failure to sync is not an
// error for an image file.
void syncFile(const std::string& path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        (void)::fsync(fd);
        ::close(fd);
    }
}

void removeQuietly(const std::string& path) {
    std::error_code ignored;
    fs::remove(path, ignored);
}

} // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writer) {
    fs::path target(path);
    fs::path folder = target.parent_path();
    std::error_code ec;
    if (!folder.empty() && !fs::is_directory(folder, ec)) {
        throw InputError("cannot write " + path + ": folder does not exist");
    }
    if (target.filename().empty()) {
        throw InputError("cannot write " + path + ": not a file name");
    }

    const std::string tmpPath = path + ".tmp-" + std::to_string(::getpid());
    try {
        writer(tmpPath);
        syncFile(tmpPath);
        fs::rename(tmpPath, target, ec);
        if (ec) {
            throw InternalError("cannot write " + path + ": " + ec.message());
        }
    } catch (...) {
        removeQuietly(tmpPath);
        throw;
    }
}

} // namespace wf
