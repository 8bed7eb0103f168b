#include "IO/Json.h"
#include "IO/Output.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <csignal>

#include <sys/inotify.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace fabguide::io;
namespace fs = std::filesystem;

namespace {

/// The folders the tests made, removed when the test program ends.
struct Made {
    std::vector<fs::path> folders;
    ~Made()
    {
        for (const fs::path& path : folders) {
            std::error_code ignored;
            fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, ignored);
            fs::remove_all(path, ignored);
        }
    }
};

/// A fresh folder of its own for each test.
fs::path folder(const std::string& name)
{
    static Made made;
    const fs::path path =
        fs::temp_directory_path() / ("fabguide-output-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
    made.folders.push_back(path);
    return path;
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream(path) << text;
}

std::string readText(const fs::path& path)
{
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Writes `count` files sheet-N.svg holding `text` into `out`, as one batch.
void writeSet(const fs::path& out, int count, const std::string& text)
{
    OutputBatch batch;
    for (int n = 1; n <= count; ++n)
        writeAtomically((out / ("sheet-" + std::to_string(n) + ".svg")).string(),
                        [&](const std::string& temporary) { writeText(temporary, text); });
    batch.commit();
}

/// "old" or "new" when all `count` files hold that, "mixed" otherwise.
std::string setIn(const fs::path& out, int count)
{
    const std::string first = readText(out / "sheet-1.svg");
    for (int n = 2; n <= count; ++n)
        if (readText(out / ("sheet-" + std::to_string(n) + ".svg")) != first)
            return "mixed";
    return first;
}

bool startsWith(const std::string& text, const std::string& start)
{
    return text.rfind(start, 0) == 0;
}

/// Waits for the first file to be renamed into `watch`'s folder.
void awaitRenamed(int watch)
{
    alignas(inotify_event) char events[4096];
    for (;;) {
        const ssize_t got = read(watch, events, sizeof events);
        for (ssize_t at = 0; at < got;) {
            const auto* event = reinterpret_cast<const inotify_event*>(events + at);
            if (event->len > 0)
                return;
            at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
        }
    }
}

}  // namespace

TEST(Output, TheTemporaryIsNewAndUnguessableSoAPlantedLinkIsNeverWrittenThrough)
{
    // A link planted where 0.1 put its temporary (.NAME.partial-PID) in a shared folder, pointing outside it.
    const fs::path shared = folder("shared"), outside = folder("outside");
    writeText((outside / "victim").string(), "kept");
    fs::create_symlink(outside / "victim", shared / (".out.json.partial-" + std::to_string(getpid())));
    std::string used;
    writeAtomically((shared / "out.json").string(), [&](const std::string& temporary) {
        used = temporary;
        struct stat made = {};
        ASSERT_EQ(lstat(temporary.c_str(), &made), 0);
        EXPECT_TRUE(S_ISREG(made.st_mode)) << "made as a plain file before it is written";
        writeText(temporary, "new");
    });
    EXPECT_EQ(readText(outside / "victim"), "kept");
    EXPECT_EQ(readText(shared / "out.json"), "new");
    EXPECT_NE(used, (shared / (".out.json.partial-" + std::to_string(getpid()))).string());
    EXPECT_FALSE(fs::exists(used));
}

TEST(Output, AFileIsReadableAsAnyTheUserMakes)
{
    // mkstemp makes its files 0600: cut sheets a workshop's other accounts could not read.
    const fs::path out = folder("mode");
    const mode_t mask = umask(022);
    writeAtomically((out / "sheet.svg").string(), [](const std::string& t) { writeText(t, "<svg/>"); });
    umask(mask);
    struct stat status = {};
    ASSERT_EQ(stat((out / "sheet.svg").c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 0777, 0644u);
}

TEST(Output, ADeviceOrPipeIsNeverReplaced)
{
    const fs::path dir = folder("pipe");
    const fs::path pipe = dir / "fifo";
    ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
    try {
        writeAtomically(pipe.string(), [](const std::string& temporary) { writeText(temporary, "x"); });
        FAIL() << "a pipe was replaced";
    } catch (const FormatError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(pipe.string() + ": not a file", 0), 0u) << e.what();
    }
    EXPECT_TRUE(fs::is_fifo(pipe));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "no temporary left";
}

TEST(Output, ARenameThatFailsAtCommitNamesItsFileAndLeavesNoTemporary)
{
    // The second file's place becomes a folder after it is written: its rename fails when the batch commits.
    // The error names it (0.1 read the name from a freed list: garbage, or a use-after-free under ASan).
    const fs::path dir = folder("commit");
    const std::string first = (dir / "a.svg").string(), second = (dir / "b.svg").string();
    OutputBatch batch;
    writeAtomically(first, [](const std::string& temporary) { writeText(temporary, "a"); });
    writeAtomically(second, [](const std::string& temporary) { writeText(temporary, "b"); });
    fs::create_directories(fs::path(second) / "in-the-way");
    try {
        batch.commit();
        FAIL() << "a rename onto a folder succeeded";
    } catch (const FormatError& e) {
        EXPECT_EQ(std::string(e.what()), second + ": cannot write file");
    }
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << entry.path();
}

TEST(Output, ThePreviousSetsLeftoversGoOnlyOnceTheNewSetIsInPlace)
{
    const fs::path out = folder("set");
    for (const char* name : {"lid.stl", "old body.stl", "mine.txt"})
        writeText((out / name).string(), "old");
    writeText(
        (out / "report.json").string(),
        R"({"format": "fabguide.printable-report", "files": ["lid.stl", "old body.stl", "report.json"]})");
    {
        OutputBatch batch;  // a run that fails before it commits: the old set stays whole
        replaceSetOf((out / "report.json").string());
        writeAtomically((out / "lid.stl").string(), [](const std::string& t) { writeText(t, "new"); });
    }
    EXPECT_TRUE(fs::exists(out / "old body.stl"));
    EXPECT_EQ(readText(out / "lid.stl"), "old");
    {
        OutputBatch batch;
        replaceSetOf((out / "report.json").string());
        writeAtomically((out / "lid.stl").string(), [](const std::string& t) { writeText(t, "new"); });
        writeAtomically((out / "report.json").string(), [](const std::string& t) { writeText(t, "{}"); });
        EXPECT_TRUE(fs::exists(out / "old body.stl")) << "not before the commit";
        batch.commit();
    }
    EXPECT_FALSE(fs::exists(out / "old body.stl")) << "a body since renamed";
    EXPECT_EQ(readText(out / "lid.stl"), "new");
    EXPECT_TRUE(fs::exists(out / "report.json") && fs::exists(out / "mine.txt"))
        << "written again, or never ours";
}

TEST(Output, AFolderThatIsALinkToNothingIsRefusedBeforeTheRunNamingWhereItLeads)
{
    const fs::path out = folder("dangling");
    fs::create_symlink(out / "nowhere", out / "link");
    for (const fs::path& asked : {out / "link", out / "link" / "sheets"}) {
        try {
            checkWritableFolder(asked.string());
            ADD_FAILURE() << asked << " taken";
        } catch (const FormatError& e) {
            EXPECT_NE(std::string(e.what()).find("is a link to " + (out / "nowhere").string() +
                                                 ", which does not exist"),
                      std::string::npos)
                << e.what();
        }
    }
    checkWritableFolder((out / "new" / "sheets").string());  // a folder to be made is fine
}

TEST(Output, ABatchWithinAnotherAddsToItsSetWhichOnlyTheOutermostCommits)
{
    const fs::path out = folder("nested");
    writeSet(out, 2, "old");
    {
        OutputBatch command;
        writeAtomically((out / "sheet-1.svg").string(), [](const std::string& t) { writeText(t, "new"); });
        {
            OutputBatch files;  // e.g. a layout's files, written within the command's batch
            writeAtomically((out / "sheet-2.svg").string(),
                            [](const std::string& t) { writeText(t, "new"); });
            files.commit();
        }
        EXPECT_EQ(setIn(out, 2), "old") << "renamed before the command commits";
    }
    EXPECT_EQ(setIn(out, 2), "old") << "the command ended without committing: nothing of it stays";
    EXPECT_EQ(std::distance(fs::directory_iterator(out), {}), 2) << "its temporaries are removed";
    {
        OutputBatch command;
        writeAtomically((out / "sheet-1.svg").string(), [](const std::string& t) { writeText(t, "new"); });
        writeSet(out, 2, "new");
        command.commit();
    }
    EXPECT_EQ(setIn(out, 2), "new");
}

TEST(Output, ASubfolderOfThePreviousSetGoesWithItsFilesButNoLinkIsFollowed)
{
    // optimise's fourth suggestion has its sheets in suggestion-4/: a run finding three left them.
    const fs::path out = folder("subfolders"), elsewhere = folder("linked");
    fs::create_directories(out / "suggestion-4");
    writeText((out / "suggestion-4" / "sheet-1.svg").string(), "old");
    writeText((elsewhere / "sheet-1.svg").string(), "kept");
    fs::create_directory_symlink(elsewhere, out / "link");
    writeText((out / "summary.json").string(),
              R"({"suggestions": [{"svg": ["suggestion-4/sheet-1.svg", "link/sheet-1.svg"]}]})");
    {
        OutputBatch batch;
        replaceSetOf((out / "summary.json").string());
        writeAtomically((out / "summary.json").string(), [](const std::string& t) { writeText(t, "{}"); });
        batch.commit();
    }
    EXPECT_FALSE(fs::exists(out / "suggestion-4"));
    EXPECT_EQ(readText(elsewhere / "sheet-1.svg"), "kept");
}

TEST(Output, AManifestNotOursOrNamingFilesElsewhereRemovesNothing)
{
    const fs::path out = folder("foreign"), elsewhere = folder("elsewhere");
    writeText((elsewhere / "victim").string(), "kept");
    writeText((out / "notes.txt").string(), "kept");
    writeText((out / "report.json").string(), R"({"files": ["notes.txt"]})");  // another tool's report
    writeText(
        (out / "summary.json").string(),
        R"({"suggestions": [], "file": ")" + (elsewhere / "victim").string() + R"(", "up": "../victim"})");
    {
        OutputBatch batch;
        replaceSetOf((out / "report.json").string());
        replaceSetOf((out / "summary.json").string());
        replaceSetOf((out / "missing.json").string());
        batch.commit();
    }
    EXPECT_TRUE(fs::exists(out / "notes.txt"));
    EXPECT_TRUE(fs::exists(elsewhere / "victim"));
}

TEST(Output, TemporariesARunThatEndedLeftAreRemovedByTheNextAndALiveRunsAreKept)
{
    const fs::path out = folder("leftovers");
    const pid_t ended = fork();
    if (ended == 0)
        _exit(0);
    waitpid(ended, nullptr, 0);  // its id names no process now
    const std::string dead = ".old.svg.partial-" + std::to_string(ended) + "-Ab12Cd";
    const std::string zipped = ".old.3mf.partial-" + std::to_string(ended) + "-Ab12Cd.xY34zW";  // libzip's
    const std::string alive =
        ".old.svg.partial-" + std::to_string(getppid()) + "-Ef34Gh";  // a run still going
    writeText((out / dead).string(), "left by a SIGKILL");
    writeText((out / zipped).string(), "left by a SIGKILL");
    writeText((out / alive).string(), "being written");
    writeText((out / ".notes.partial-draft").string(), "someone's");
    writeAtomically((out / "new.svg").string(), [](const std::string& t) { writeText(t, "new"); });
    EXPECT_FALSE(fs::exists(out / dead));
    EXPECT_FALSE(fs::exists(out / zipped));
    EXPECT_TRUE(fs::exists(out / alive));
    EXPECT_TRUE(fs::exists(out / ".notes.partial-draft"));
    EXPECT_EQ(readText(out / "new.svg"), "new");
}

TEST(Output, TemporariesARunKilledWhileWritingALargerSetLeftInAFolderNoManifestNamesAreRemoved)
{
    // optimise killed while writing suggestion-3/, then run again finding two: no summary names that folder.
    const fs::path out = folder("larger"), kept = out / "drawings";
    const pid_t ended = fork();
    if (ended == 0)
        _exit(0);
    waitpid(ended, nullptr, 0);
    const std::string pid = std::to_string(ended);
    fs::create_directories(out / "suggestion-3");
    fs::create_directories(kept);
    writeText((out / "suggestion-3" / (".sheet-1.svg.partial-" + pid + "-Ab12Cd")).string(), "cut short");
    writeText((out / "suggestion-3" / ("..fabguide-commit-.partial-" + pid + "-Ef34Gh")).string(), "{");
    writeText((kept / (".sheet-1.svg.partial-" + std::to_string(getppid()) + "-Ab12Cd")).string(), "alive");
    writeText((kept / "notes.txt").string(), "the user's");
    {
        OutputBatch batch;
        replaceSetOf((out / "summary.json").string());  // none yet
        writeAtomically((out / "summary.json").string(), [](const std::string& t) { writeText(t, "{}"); });
        batch.commit();
    }
    EXPECT_FALSE(fs::exists(out / "suggestion-3"));
    EXPECT_EQ(std::distance(fs::directory_iterator(kept), fs::directory_iterator()), 2);
}

TEST(Output, ABareFileNameIsWrittenInTheWorkingFolder)
{
    // `fabguide solve in.json -o out.json`, the commonest call, failed: its folder is "".
    const fs::path here = folder("bare"), was = fs::current_path();
    fs::current_path(here);
    EXPECT_NO_THROW(
        writeAtomically("out.json", [](const std::string& temporary) { writeText(temporary, "written"); }));
    fs::current_path(was);
    EXPECT_EQ(readText(here / "out.json"), "written");
}

TEST(Output, ASetAKillCutShortDuringItsRenamesIsCompletedWholeByTheNextRun)
{
    // SIGKILL cannot be held off: a run killed while renaming its batch left some files old, some new.
    const fs::path out = folder("killed");
    const int count = 3000;
    for (int attempt = 0; attempt < 5; ++attempt) {
        writeSet(out, count, "old");
        const int watch = inotify_init1(0);
        inotify_add_watch(watch, out.c_str(), IN_MOVED_TO);
        const pid_t run = fork();
        if (run == 0) {
            writeSet(out, count, "new");
            _exit(0);
        }
        awaitRenamed(watch);  // the commit has begun
        kill(run, SIGKILL);
        int status = 0;
        waitpid(run, &status, 0);
        close(watch);
        if (!WIFSIGNALED(status))
            continue;  // the run had finished before the kill: try again
        completeInterruptedRuns(out.string());
        EXPECT_EQ(setIn(out, count), "new");
        for (const auto& entry : fs::directory_iterator(out))
            EXPECT_FALSE(startsWith(entry.path().filename().string(), ".")) << entry.path();
        return;
    }
    GTEST_SKIP() << "every run finished its renames before the kill reached it";
}

TEST(Output, AJournalSomeoneElsePlantedOrOfALiveRunIsNotFollowed)
{
    const fs::path out = folder("planted");
    writeText((out / "report.json").string(), "mine");
    writeText((out / ".x.partial-1-Ab12Cd").string(), "planted");  // process 1 is alive: never a leftover
    writeText((out / ".fabguide-commit-1-Ab12Cd").string(),
              R"({"renames": [[".x.partial-1-Ab12Cd", "report.json"]], "removes": ["report.json"]})");
    const pid_t ended = fork();
    if (ended == 0)
        _exit(0);
    waitpid(ended, nullptr, 0);
    const std::string pid = std::to_string(ended);
    writeText((out / (".fabguide-commit-" + pid + "-Ef34Gh")).string(),
              R"({"renames": [["../elsewhere", "report.json"], [".y.partial-)" + pid +
                  R"(-Ef34Gh", "/etc/passwd"]], "removes": ["../report.json", "/etc/passwd"]})");
    completeInterruptedRuns(out.string());
    EXPECT_EQ(readText(out / "report.json"), "mine");
    EXPECT_TRUE(fs::exists(out / ".fabguide-commit-1-Ab12Cd"));
    EXPECT_FALSE(fs::exists(out / (".fabguide-commit-" + pid + "-Ef34Gh")));
}

/// A batch's journals in folders a and b of `out`, as an ended run left them: each lists its temporary for
/// sheet.svg and the batch; the journal of b only when `bothWritten`.
pid_t twoFolderBatch(const fs::path& out, bool bothWritten)
{
    const pid_t ended = fork();
    if (ended == 0)
        _exit(0);
    waitpid(ended, nullptr, 0);
    const std::string pid = std::to_string(ended);
    const fs::path a = out / "a", b = out / "b";
    const std::string batch = "[\"" + (a / (".fabguide-commit-" + pid + "-Ab12Cd")).string() + "\", \"" +
                              (b / (".fabguide-commit-" + pid + "-Ef34Gh")).string() + "\"]";
    for (const auto& [folder, suffix] : {std::pair{a, "Ab12Cd"}, std::pair{b, "Ef34Gh"}}) {
        fs::create_directories(folder);
        writeText((folder / "sheet.svg").string(), "old");
        const std::string temporary = ".sheet.svg.partial-" + pid + "-" + suffix;
        writeText((folder / temporary).string(), "new");
        if (folder == a || bothWritten)
            writeText((folder / (".fabguide-commit-" + pid + "-" + suffix)).string(),
                      R"({"renames": [[")" + temporary + R"(", "sheet.svg"]], "batch": )" + batch + "}");
    }
    return ended;
}

TEST(Output, ABatchKilledWhileWritingItsJournalsIsNotCompletedInAnyFolder)
{
    // The kill came after folder a's journal and before folder b's: no rename had begun, so the old set stays
    // (completing a alone left a mixed set: found by the kill test, an optimise run of several folders).
    const fs::path out = folder("half-journalled");
    twoFolderBatch(out, false);
    completeInterruptedRuns((out / "a").string());
    completeInterruptedRuns((out / "b").string());
    EXPECT_EQ(readText(out / "a" / "sheet.svg"), "old");
    EXPECT_EQ(readText(out / "b" / "sheet.svg"), "old");
    EXPECT_EQ(std::distance(fs::directory_iterator(out / "a"), {}), 1) << "journal and temporary gone";
}

TEST(Output, ABatchWhoseJournalsAreAllWrittenIsCompletedInEveryFolderByTheFirstRunToFindOne)
{
    const fs::path out = folder("journalled");
    twoFolderBatch(out, true);
    completeInterruptedRuns((out / "b").string());  // a run that only reads folder b
    EXPECT_EQ(readText(out / "a" / "sheet.svg"), "new");
    EXPECT_EQ(readText(out / "b" / "sheet.svg"), "new");
    EXPECT_EQ(std::distance(fs::directory_iterator(out / "a"), {}), 1) << "a's journal went with b's";
}

TEST(Output, ASetCutShortInASubfolderTheNextRunNoLongerWritesIsCompletedThenReplaced)
{
    // optimise killed while renaming a third suggestion's sheets; the next run finds two: suggestion-3/ kept
    // its journal and temporary, as no run wrote there again.
    const fs::path out = folder("subfolder-journal");
    const pid_t ended = fork();
    if (ended == 0)
        _exit(0);
    waitpid(ended, nullptr, 0);
    const std::string temporary = ".sheet-1.svg.partial-" + std::to_string(ended) + "-Ab12Cd";
    fs::create_directories(out / "suggestion-3");
    writeText((out / "suggestion-3" / temporary).string(), "new");
    writeText((out / "suggestion-3" / (".fabguide-commit-" + std::to_string(ended) + "-Ab12Cd")).string(),
              R"({"renames": [[")" + temporary + R"(", "sheet-1.svg"]]})");
    writeText((out / "summary.json").string(), R"({"suggestions": [{"svg": ["suggestion-3/sheet-1.svg"]}]})");
    {
        OutputBatch batch;
        replaceSetOf((out / "summary.json").string());
        writeAtomically((out / "summary.json").string(), [](const std::string& t) { writeText(t, "{}"); });
        batch.commit();
    }
    EXPECT_FALSE(fs::exists(out / "suggestion-3"));
}
