#include "IO/Output.h"

#include "IO/Json.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include <signal.h>
#include <unistd.h>

namespace fabguide::io {

namespace {

struct File {
    std::string temporary, path;
    bool written = false;
};

/// The files under temporary names. The signal handler reads the list only while no thread changes it.
struct Pending {
    std::vector<File> files;
    std::vector<std::string> stale;  ///< removed once the batch commits, unless written
    int batches = 0;
    std::mutex mutex;
    std::atomic<bool> changing{false};
};
Pending& pending()
{
    static Pending instance;
    return instance;
}

/// The list taken for a change: other threads wait on the mutex, the signal handler on `changing`, and
/// SIGINT / SIGTERM are held in this thread (its handler would wait on itself).
class Changing {
public:
    Changing() : guard_(pending().mutex)
    {
        sigset_t both;
        sigemptyset(&both);
        sigaddset(&both, SIGINT);
        sigaddset(&both, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &both, &before_);
        pending().changing = true;
    }
    ~Changing()
    {
        pending().changing = false;
        pthread_sigmask(SIG_SETMASK, &before_, nullptr);
    }
    Changing(const Changing&) = delete;
    Changing& operator=(const Changing&) = delete;

private:
    std::lock_guard<std::mutex> guard_;
    sigset_t before_;
};

/// Whether `path` is free to be replaced by a file: nothing there, a regular file, or a link (replaced
/// itself, never followed). A device, pipe, socket or folder is not: as root, renaming over /dev/null would
/// replace it.
bool replaceable(const std::string& path)
{
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::symlink_status(path, error);
    return !std::filesystem::exists(status) || std::filesystem::is_regular_file(status) ||
           std::filesystem::is_symlink(status);
}

/// Renames `file` into place; false if that failed (the temporary is then removed).
bool rename(const File& file)
{
    if (replaceable(file.path) && std::rename(file.temporary.c_str(), file.path.c_str()) == 0)
        return true;
    std::remove(file.temporary.c_str());
    return false;
}

void removeAll()
{
    for (const File& file : pending().files)
        std::remove(file.temporary.c_str());
    pending().files.clear();
}

extern "C" void onInterrupt(int signal)
{
    while (pending().changing)  // another thread is changing the list: it finishes soon
        ;
    for (const File& file : pending().files)  // unlink and _exit are async-signal-safe
        unlink(file.temporary.c_str());
    _exit(128 + signal);
}

/// Removes, once per folder and process, the temporaries that runs since ended left in `folder` (killed by
/// SIGKILL, or the machine stopped): `.NAME.partial-PID-XXXXXX` whose process no longer exists. One still
/// running (another run writing there now) keeps its own.
void removeLeftovers(const std::filesystem::path& folder)
{
    static std::mutex once;
    static std::vector<std::string> cleaned;
    const std::lock_guard<std::mutex> guard(once);
    const std::filesystem::path here = folder.empty() ? "." : folder;  // a bare file name: the working folder
    const std::string key = std::filesystem::absolute(here).lexically_normal().string();
    if (std::find(cleaned.begin(), cleaned.end(), key) != cleaned.end())
        return;
    cleaned.push_back(key);
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(here, error)) {
        const std::string name = entry.path().filename().string();
        const size_t at = name.rfind(".partial-");
        if (name[0] != '.' || at == std::string::npos || name.size() < at + 9 + 8)
            continue;
        const std::string pid = name.substr(at + 9, name.size() - at - 9 - 7);  // PID of PID-XXXXXX
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9)
            continue;
        if (kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH &&
            entry.is_regular_file(error))
            std::filesystem::remove(entry.path(), error);
    }
}

/// A new empty file beside `path` under a name no one can guess, made by this call alone (mkstemp: O_CREAT |
/// O_EXCL, so a link planted in a shared folder is never written through). It carries this process's id, so a
/// later run can tell a temporary whose run has ended (removeLeftovers).
std::string temporaryFor(const std::string& path)
{
    const std::filesystem::path p(path);
    removeLeftovers(p.parent_path());
    std::string name =
        (p.parent_path() / ("." + p.filename().string() + ".partial-" + std::to_string(getpid()) + "-XXXXXX"))
            .string();
    const int fd = mkstemp(name.data());
    if (fd < 0)
        throw FormatError(path + ": cannot write beside it (" + std::strerror(errno) + ")");
    close(fd);
    return name;
}

}  // namespace

void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write)
{
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::create_directories(folder, error) && error)
        throw FormatError(folder.string() + ": cannot create folder (" + error.message() + ")");
    if (!replaceable(path))
        throw FormatError(path + ": not a file (a device, pipe or folder is never replaced)");
    const File file{temporaryFor(path), path};
    {
        Changing changing;
        pending().files.push_back(file);
    }
    const auto forget = [&] {
        Changing changing;
        auto& files = pending().files;
        for (auto it = files.begin(); it != files.end(); ++it)
            if (it->temporary == file.temporary) {
                files.erase(it);
                break;
            }
    };
    try {
        write(file.temporary);
    } catch (...) {
        std::remove(file.temporary.c_str());
        forget();
        throw;
    }
    {
        Changing changing;
        if (pending().batches > 0) {
            for (File& f : pending().files)
                f.written = f.written || f.temporary == file.temporary;
            return;
        }
    }
    const bool renamed = rename(file);
    forget();
    if (!renamed)
        throw FormatError(path + ": cannot write file");
}

OutputBatch::OutputBatch()
{
    Changing changing;
    ++pending().batches;
}

OutputBatch::~OutputBatch()
{
    Changing changing;
    if (--pending().batches == 0) {
        removeAll();
        pending().stale.clear();
    }
}

void OutputBatch::commit()
{
    Changing changing;
    std::vector<std::string> written;
    for (const File& file : pending().files)
        if (file.written) {
            if (!rename(file)) {
                const std::string path = file.path;  // removeAll frees `file`
                removeAll();
                throw FormatError(path + ": cannot write file");
            }
            written.push_back(std::filesystem::absolute(file.path).lexically_normal().string());
        }
    pending().files.clear();
    for (const std::string& path : pending().stale)
        if (std::find(written.begin(), written.end(), path) == written.end())
            std::remove(path.c_str());
    pending().stale.clear();
}

void removeWhenCommitted(const std::string& path)
{
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    Changing changing;
    if (pending().batches == 0)
        std::remove(absolute.c_str());
    else
        pending().stale.push_back(absolute);
}

void replaceSetOf(const std::string& manifest)
{
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::absolute(manifest).lexically_normal().parent_path();
    nlohmann::json listed;
    try {
        listed = readJsonFile(manifest);
    } catch (const std::exception&) {
        return;  // none yet
    }
    if (!listed.is_object() ||
        (listed.value("format", "").rfind("fabguide.", 0) != 0 && !listed.contains("suggestions")))
        return;  // not one of ours: nothing it names is touched
    std::vector<const nlohmann::json*> todo{&listed};
    while (!todo.empty()) {
        const nlohmann::json& node = *todo.back();
        todo.pop_back();
        if (node.is_structured())
            for (const nlohmann::json& child : node)
                todo.push_back(&child);
        if (!node.is_string())
            continue;
        const std::filesystem::path named(node.get<std::string>());
        for (const std::filesystem::path& file : {folder / named, std::filesystem::absolute(named)}) {
            const std::filesystem::path normal = file.lexically_normal();
            if (normal.parent_path() == folder &&
                std::filesystem::is_regular_file(std::filesystem::symlink_status(normal, error)))
                removeWhenCommitted(normal.string());
        }
    }
}

void removeTemporariesOnInterrupt()
{
    struct sigaction action = {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

void checkWritableFolder(const std::string& folder)
{
    std::error_code error;
    std::filesystem::path p = std::filesystem::absolute(folder, error);
    while (p.has_relative_path() && !std::filesystem::exists(p, error))
        p = p.parent_path();  // the nearest folder that exists is where the new ones would be made
    if (!std::filesystem::is_directory(p, error))
        throw FormatError(folder + ": not a folder (" + p.string() + " is a file)");
    if (access(p.c_str(), W_OK | X_OK) != 0)
        throw FormatError(folder + ": cannot write there (" + p.string() + " is not writable)");
}

void checkWritableFile(const std::string& file)
{
    std::error_code error;
    if (std::filesystem::is_directory(file, error))
        throw FormatError(file + ": is a folder, not a file to write");
    checkWritableFolder(std::filesystem::absolute(file, error).parent_path().string());
}

}  // namespace fabguide::io
