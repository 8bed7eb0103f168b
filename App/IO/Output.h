// Output files that are never seen half-written: each is written under a temporary name beside its final one
// and renamed into place, at once, or, while an OutputBatch is open, all together when the batch commits, so
// a run stopped at any moment leaves the files of the run before it, never a truncated or mixed set. A batch
// killed during its renames leaves a journal that the next run completes (completeInterruptedRuns).
#pragma once

#include <functional>
#include <string>

namespace fabguide::io {

/// Calls write(temporary) for a temporary name beside `path` (its folder made if need be), then renames it to
/// `path`: at once, or when the open OutputBatch commits. The temporary is removed if write throws, or if the
/// process is interrupted.
void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write);

/// The output of one command: files written while it is open are renamed when it commits; those not
/// committed are removed when it closes (an error, an exception). Within another batch it adds to that one's
/// set: only the outermost commits and removes.
class OutputBatch {
public:
    OutputBatch();
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;
    /// Renames every file written into place, an interruption held off until the last is renamed.
    void commit();
};

/// Removes `path` once the open OutputBatch has committed (at once when none is open), unless the batch wrote
/// it: a file of the previous set that the new set does not have goes only when the new set is in place.
void removeWhenCommitted(const std::string& path);

/// Every file that `manifest` (a JSON file an earlier run wrote beside its outputs: summary.json,
/// report.json) names in its folder, removed when the batch commits unless written again: the previous set's
/// leftovers (a body since renamed, a suggestion not found again). A manifest that is missing or does not
/// read names none. What ended runs left in the folders directly in its folder is tidied first
/// (completeInterruptedRuns): a run killed while writing a larger set made folders no manifest names.
void replaceSetOf(const std::string& manifest);

/// Tidies what runs since ended left in `folder`: a commit a kill cut short is completed (its journal's
/// renames done, so the set is all new), then their temporaries are removed. Done before a file in it is
/// read, and before the first file a process writes there.
void completeInterruptedRuns(const std::string& folder);

/// On SIGINT or SIGTERM: removes every temporary file not yet renamed and exits with 128 + the signal
/// (130, 143). Installed by the command-line tool.
void removeTemporariesOnInterrupt();

/// Throws FormatError naming `folder` unless it exists as a folder we may write in, or can be made (a link to
/// nothing cannot).
void checkWritableFolder(const std::string& folder);

/// Throws FormatError naming `file` unless it is not a folder and its folder passes checkWritableFolder.
void checkWritableFile(const std::string& file);

}  // namespace fabguide::io
