#pragma once
// Writing output files so that a failure never leaves a partial or corrupted file behind:
// the content goes to a temporary file in the destination's directory, which is renamed
// over the destination only after the writer returned successfully.
#include <functional>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace toposlam::io {

/// Calls `writeTo(tmpPath)`, then renames tmpPath to `path`. If `writeTo` throws, or the
/// rename fails, the temporary file is removed and the exception propagates (rename failure:
/// std::runtime_error naming `path`). The temporary name keeps the destination's extension
/// (e.g. "map.tmp123.gridmap.gz"), so writers that pick a format by extension still work.
/// Not every library reports a failed write (cv::imwrite and MRPT's gzip stream close their
/// files unchecked), so before the rename the file on disk is checked: a full device, a PNG
/// without its IEND chunk and a gzip stream cut short are errors naming `path`. Inside an
/// OutputGroup (below) the rename waits for the group's commit().
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writeTo);

/// Inside a catch block: rethrows the exception being handled, an MRPT stream's failed write
/// ("Cannot write bytes to stream!") as std::runtime_error naming `path` and the reason.
[[noreturn]] void rethrowWriteError(const std::string& path);

/// The same guarantee for output written incrementally (streams that stay open while a log
/// is converted): write to temporaryPath(), then commit(). Destroyed without commit() (an
/// exception, an early return), it removes the temporary file and leaves `path` untouched.
class TemporaryOutputFile {
  public:
    explicit TemporaryOutputFile(std::string path);
    ~TemporaryOutputFile();
    TemporaryOutputFile(const TemporaryOutputFile&) = delete;
    TemporaryOutputFile& operator=(const TemporaryOutputFile&) = delete;

    /// Where to write: same directory and extension as the destination.
    const std::string& temporaryPath() const { return tmpPath_; }
    const std::string& path() const { return path_; }
    /// Checks the temporary file as writeFileAtomically does and renames it to path(). Throws
    /// std::runtime_error naming path() if either fails (the temporary file is then removed).
    void commit();
    bool committed() const { return committed_; }

  private:
    std::string path_, tmpPath_;
    bool committed_ = false;
};

/// Outputs that belong together (a SLAM run's trajectory, grids, keyframes and summary): all
/// of them or none. While a group is open on a thread, writeFileAtomically and
/// TemporaryOutputFile::commit on that thread check each file but leave it under its
/// temporary name; commit() then renames them all. Destroyed without commit() (a later
/// output failed), the group removes them, so the destination keeps what it held before
/// instead of a mix of two runs. Groups nest: an inner group commits into the outer one.
/// Open, commit and destroy a group on one thread; other threads join it explicitly.
class OutputGroup {
  public:
    OutputGroup();
    ~OutputGroup();
    OutputGroup(const OutputGroup&) = delete;
    OutputGroup& operator=(const OutputGroup&) = delete;

    /// Renames every file written in the group to its destination, in the order written.
    /// A destination that is a folder is an error before anything is renamed. Throws
    /// std::runtime_error naming the file whose rename failed (the remaining temporaries are
    /// then removed; files renamed before it stay).
    void commit();

    /// While the returned object lives, writes on the calling thread (e.g. a std::async task
    /// the group's thread waits for) belong to this group too.
    class ThreadMembership {
      public:
        explicit ThreadMembership(OutputGroup& group);
        ~ThreadMembership();
        ThreadMembership(const ThreadMembership&) = delete;
        ThreadMembership& operator=(const ThreadMembership&) = delete;

      private:
        OutputGroup* previous_;
    };
    [[nodiscard]] ThreadMembership joinFromThisThread() { return ThreadMembership(*this); }

    /// Takes over a checked temporary file, to be renamed to `path` by commit(). Used by the
    /// writers above; a later file for the same `path` replaces the earlier one.
    void add(std::string temporaryPath, std::string path);

  private:
    std::mutex mutex_;
    std::vector<std::pair<std::string, std::string>> files_;  // temporary, destination
    OutputGroup* outer_;
    bool committed_ = false;
};

}  // namespace toposlam::io
