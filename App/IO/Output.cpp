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
#include <fstream>
#include <map>
#include <mutex>
#include <vector>

#include <signal.h>
#include <sys/stat.h>
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

/// Takes `changing` (false to true), waiting while another holder has it: a change of the list, or the
/// signal handler, which never gives it back. So a handler in another thread cannot remove temporaries a
/// commit is renaming, and a commit cannot begin once a handler has begun (a kill during the renames left a
/// journal naming temporaries the handler had removed: a mixed set).
void takeChanging()
{
    for (bool free = false; !pending().changing.compare_exchange_weak(free, true); free = false)
        ;
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
        takeChanging();
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
    takeChanging();  // another thread changing the list finishes first; none begins after
    for (const File& file : pending().files)  // unlink and _exit are async-signal-safe
        unlink(file.temporary.c_str());
    _exit(128 + signal);
}

/// The process id a leftover's name carries after `marker` (`.NAME.partial-PID-XXXXXX`, and libzip's
/// temporary of it `.NAME.partial-PID-XXXXXX.abcdef`; `.fabguide-commit-PID-XXXXXX`), or 0 when the name is
/// not ours.
pid_t leftoverOf(const std::string& name, const std::string& marker)
{
    const size_t at = name.rfind(marker), start = at + marker.size();
    if (name.empty() || name[0] != '.' || at == std::string::npos)
        return 0;
    const size_t end = name.find('-', start);  // then XXXXXX, and what a writer adds (libzip's own temporary)
    const std::string pid = name.substr(start, end == std::string::npos ? 0 : end - start);
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9)
        return 0;
    return static_cast<pid_t>(std::stol(pid));
}

/// Whether `path` is a regular file of this user that a process since ended left: only those are touched,
/// so a file someone else planted in a shared folder never is.
bool leftByEndedRun(const std::filesystem::path& path, pid_t pid)
{
    struct stat status = {};
    return pid > 0 && kill(pid, 0) != 0 && errno == ESRCH && lstat(path.c_str(), &status) == 0 &&
           S_ISREG(status.st_mode) && status.st_uid == geteuid();
}

const std::string kJournal = ".fabguide-commit-";

/// A plain file name in the journal's folder (no folder part, not `.` or `..`).
bool plainName(const nlohmann::json& name)
{
    if (!name.is_string())
        return false;
    const std::string text = name.get<std::string>();
    return !text.empty() && text != "." && text != ".." && text.find('/') == std::string::npos;
}

nlohmann::json readJournal(const std::filesystem::path& journal)
{
    std::ifstream in(journal);
    const nlohmann::json listed =
        nlohmann::json::parse(in, nullptr, false);  // discarded when it does not read
    return listed.is_object() ? listed : nlohmann::json::object();
}

/// The renames and removals one journal lists in its own folder, done where its temporaries remain.
void applyJournal(const std::filesystem::path& journal, pid_t pid)
{
    const std::filesystem::path folder = journal.parent_path();
    const nlohmann::json listed = readJournal(journal);
    for (const nlohmann::json& rename : listed.value("renames", nlohmann::json::array())) {
        if (!rename.is_array() || rename.size() != 2 || !plainName(rename[0]) || !plainName(rename[1]))
            continue;
        const std::filesystem::path from = folder / rename[0].get<std::string>();
        const std::filesystem::path to = folder / rename[1].get<std::string>();
        if (leftoverOf(from.filename().string(), ".partial-") == pid && leftByEndedRun(from, pid) &&
            replaceable(to.string()))
            std::rename(from.c_str(), to.c_str());
    }
    std::error_code error;
    for (const nlohmann::json& name : listed.value("removes", nlohmann::json::array()))
        if (plainName(name) && std::filesystem::is_regular_file(
                                   std::filesystem::symlink_status(folder / name.get<std::string>(), error)))
            std::filesystem::remove(folder / name.get<std::string>(), error);
}

/// Completes the commit a killed run's journals describe, in every folder it touched: the temporaries still
/// there are renamed into place and the leftovers removed, so the set is whole and new, as if the kill had
/// come a moment later. Each journal names the batch's journals in every folder; unless all are there (this
/// user's, of the ended run), the commit either had not begun its renames (its journals were being written)
/// or had done them all (they were being removed), so nothing is renamed and the journal just goes.
void rollForward(const std::filesystem::path& journal, pid_t pid)
{
    std::error_code error;
    const std::filesystem::path self = std::filesystem::absolute(journal, error).lexically_normal();
    std::vector<std::filesystem::path> batch;
    for (const nlohmann::json& sibling : readJournal(journal).value(
             "batch", nlohmann::json::array({self.string()})))  // one folder's, earlier
        if (sibling.is_string())
            batch.emplace_back(sibling.get<std::string>());
    const std::string named = kJournal + std::to_string(pid) + "-";
    const bool whole = std::find(batch.begin(), batch.end(), self) != batch.end() &&
                       std::all_of(batch.begin(), batch.end(), [&](const std::filesystem::path& sibling) {
                           return sibling.is_absolute() && sibling.filename().string().rfind(named, 0) == 0 &&
                                  leftByEndedRun(sibling, pid);
                       });
    if (!whole)
        batch = {self};
    else
        for (const std::filesystem::path& sibling : batch)
            applyJournal(sibling, pid);
    for (const std::filesystem::path& sibling : batch) {
        std::filesystem::remove(sibling, error);
        rmdir(sibling.parent_path().c_str());  // a folder its removals left empty goes too
    }
}

/// Tidies what runs since ended left in `folder` (killed by SIGKILL, or the machine stopped): first a commit
/// cut short is completed (rollForward), then the temporaries `.NAME.partial-PID-XXXXXX` of ended processes
/// are removed. A run still going keeps its own.
void removeLeftovers(const std::filesystem::path& folder)
{
    std::error_code error;
    for (const std::string& marker : {kJournal, std::string(".partial-")})
        for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
            const std::string name = entry.path().filename().string();
            const pid_t pid = leftoverOf(name, marker);
            if ((marker == kJournal && name.rfind(kJournal, 0) != 0) || !leftByEndedRun(entry.path(), pid))
                continue;  // a journal's name begins with its marker; leftoverOf checked the rest
            if (marker == kJournal)
                rollForward(entry.path(), pid);
            else
                std::filesystem::remove(entry.path(), error);
        }
}

/// removeLeftovers before the first file this process writes in `folder`.
void removeLeftoversOnce(const std::filesystem::path& folder)
{
    static std::mutex once;
    static std::vector<std::string> cleaned;
    const std::lock_guard<std::mutex> guard(once);
    std::error_code error;
    const std::string key = std::filesystem::absolute(folder, error).lexically_normal().string();
    if (std::find(cleaned.begin(), cleaned.end(), key) == cleaned.end()) {
        cleaned.push_back(key);
        removeLeftovers(folder);
    }
}

/// removeLeftoversOnce in the folders directly in a set's `folder` (suggestion-N/), which a run killed while
/// writing a larger set may have made and the next set does not name; one its tidying leaves empty goes too.
void removeLeftoversBelow(const std::filesystem::path& folder)
{
    std::error_code error;
    struct stat status = {};
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (lstat(entry.path().c_str(), &status) == 0 && S_ISDIR(status.st_mode) &&
            status.st_uid == geteuid()) {
            const bool wasEmpty = std::filesystem::is_empty(entry.path(), error);
            removeLeftoversOnce(entry.path());
            if (!wasEmpty)
                rmdir(entry.path().c_str());  // fails unless the tidying left it empty
        }
}

/// A new empty file beside `path` under a name no one can guess, made by this call alone (mkstemp: O_CREAT |
/// O_EXCL, so a link planted in a shared folder is never written through). It carries this process's id, so a
/// later run can tell a temporary whose run has ended (removeLeftovers).
std::string temporaryFor(const std::string& path)
{
    const std::filesystem::path p(path);
    removeLeftoversOnce(p.parent_path().empty() ? "." : p.parent_path());  // a bare name: the working folder
    std::string name =
        (p.parent_path() / ("." + p.filename().string() + ".partial-" + std::to_string(getpid()) + "-XXXXXX"))
            .string();
    const int fd = mkstemp(name.data());
    if (fd < 0)
        throw FormatError(path + ": cannot write beside it (" + std::strerror(errno) + ")");
    static const mode_t mask = [] {  // read once: umask can only be read by setting it
        const mode_t was = umask(0);
        umask(was);
        return was;
    }();
    fchmod(fd, 0666 & ~mask);  // as any file the user makes: mkstemp's are private (0600)
    close(fd);
    return name;
}

/// Writes, in each folder the commit touches, a journal `.fabguide-commit-PID-XXXXXX` of what it renames
/// and removes there, and the names of the batch's journals in all folders ("batch"), before the first
/// rename; removed after the last. A run killed between them leaves them, and the next run to use any of the
/// folders completes the commit in all of them (rollForward): the set is then all new.
std::vector<std::filesystem::path> writeJournals(const std::vector<File>& renames,
                                                 const std::vector<std::string>& removes)
{
    std::map<std::filesystem::path, nlohmann::json> byFolder;
    const auto inFolder = [&](const std::string& path) -> std::pair<nlohmann::json&, std::string> {
        const std::filesystem::path normal = std::filesystem::absolute(path).lexically_normal();
        nlohmann::json& journal = byFolder[normal.parent_path()];
        journal["format"] = "fabguide.commit";
        return {journal, normal.filename().string()};
    };
    for (const File& file : renames) {
        auto [journal, name] = inFolder(file.path);
        journal["renames"].push_back({std::filesystem::path(file.temporary).filename().string(), name});
    }
    for (const std::string& path : removes) {
        auto [journal, name] = inFolder(path);
        journal["removes"].push_back(name);
    }
    std::vector<std::string> temporaries;
    nlohmann::json batch = nlohmann::json::array();
    for (const auto& [folder, journal] : byFolder) {
        temporaries.push_back(temporaryFor((folder / kJournal).string()));
        batch.push_back((folder / (kJournal + std::to_string(getpid()) +
                                   temporaries.back().substr(temporaries.back().size() - 7)))
                            .string());
    }
    std::vector<std::filesystem::path> journals;
    size_t k = 0;
    for (auto& [folder, journal] : byFolder) {
        const std::string& temporary = temporaries[k];
        const std::filesystem::path named = batch[k++].get<std::string>();
        journal["batch"] = batch;
        std::ofstream out(temporary);
        out << journal.dump();
        out.close();
        if (!out || std::rename(temporary.c_str(), named.c_str()) != 0) {
            for (const std::string& left : temporaries)
                std::remove(left.c_str());
            for (const std::filesystem::path& made : journals)
                std::remove(made.c_str());
            throw FormatError(folder.string() +
                              ": cannot write there (no room for the list of files to replace)");
        }
        journals.push_back(named);
    }
    return journals;
}

/// Whether `inner` is `folder` or a folder in it, links followed (a link out of the folder is not in it).
bool within(const std::filesystem::path& inner, const std::filesystem::path& folder)
{
    std::error_code error;
    const std::filesystem::path real = std::filesystem::weakly_canonical(inner, error);
    const auto [end, at] = std::mismatch(folder.begin(), folder.end(), real.begin(), real.end());
    return !error && end == folder.end();
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
    if (pending().batches > 1)  // a batch within another: the outermost renames the whole set
        return;
    std::vector<File> renames;
    std::vector<std::string> written, removes;
    for (const File& file : pending().files)
        if (file.written) {
            renames.push_back(file);
            written.push_back(std::filesystem::absolute(file.path).lexically_normal().string());
        }
    for (const std::string& path : pending().stale)
        if (std::find(written.begin(), written.end(), path) == written.end())
            removes.push_back(path);
    std::vector<std::filesystem::path> journals;
    try {
        if (renames.size() + removes.size() > 1)  // one rename is whole by itself
            journals = writeJournals(renames, removes);
    } catch (...) {
        removeAll();
        throw;
    }
    for (const File& file : renames)
        if (!rename(file)) {
            removeAll();
            throw FormatError(file.path + ": cannot write file");
        }
    pending().files.clear();
    for (const std::string& path : removes)
        std::remove(path.c_str());
    pending().stale.clear();
    for (const std::filesystem::path& journal : journals)
        std::remove(journal.c_str());
    for (const std::string& path : removes)
        rmdir(std::filesystem::path(path).parent_path().c_str());  // a folder they leave empty goes too
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
    const std::filesystem::path folder =
        std::filesystem::weakly_canonical(std::filesystem::absolute(manifest).parent_path(), error);
    removeLeftoversBelow(folder);  // a killed run's, named by no manifest
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
        if (!node.is_string() || node.get_ref<const std::string&>().empty())  // "": a value, no file
            continue;
        const std::filesystem::path named(node.get<std::string>());
        for (const std::filesystem::path& file : {folder / named, std::filesystem::absolute(named, error)}) {
            const std::filesystem::path normal = file.lexically_normal();
            if (!within(normal.parent_path(), folder))
                continue;
            removeLeftoversOnce(normal.parent_path());  // a set a kill cut short there, completed first
            if (std::filesystem::is_regular_file(std::filesystem::symlink_status(normal, error)))
                removeWhenCommitted(normal.string());
        }
    }
}

void completeInterruptedRuns(const std::string& folder)
{
    removeLeftovers(folder.empty() ? "." : folder);
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
    while (p.has_relative_path() && !std::filesystem::exists(std::filesystem::symlink_status(p, error)))
        p = p.parent_path();  // the nearest folder that exists is where the new ones would be made
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(p, error)) &&
        !std::filesystem::exists(p, error))
        throw FormatError(folder + ": " + p.string() + " is a link to " +
                          std::filesystem::read_symlink(p, error).string() +
                          ", which does not exist; make that folder, or name another");
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
