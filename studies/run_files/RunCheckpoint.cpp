#include "studies/run_files/RunCheckpoint.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "files/SideFiles.hpp"
#include "h5/AtomicFile.hpp"
#include "h5/H5Error.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/H5mdWriter.hpp"
#include "particles/StateArchive.hpp"

namespace granwave {

namespace {
constexpr const char* kFormat = "granwave-checkpoint-1";
}  // namespace

RunCheckpoint::RunCheckpoint(std::string run_path, std::string identity)
    : run_path_(std::move(run_path)),
      state_path_(run_path_ + ".checkpoint"),
      identity_(std::move(identity)) {
  const std::string lock = run_path_ + ".lock";
  // The holder unlinks the lock file when done; a process that opened the file before that
  // would hold a lock on a name no one else sees, so it checks that the file it locked is
  // still the one at the path, and tries again if not.
  for (int attempt = 0; attempt < 100; ++attempt) {
    lock_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock_ < 0)
      throw CheckpointError(lock + ": cannot create the run's lock file (" + std::strerror(errno) +
                            ")");
    if (::flock(lock_, LOCK_EX | LOCK_NB) != 0) {
      ::close(lock_);
      lock_ = -1;
      throw CheckpointError(run_path_ + ": another granwave process is making this run (it holds " +
                            lock + "); wait for it or stop it");
    }
    struct stat held {
    }, named{};
    if (::fstat(lock_, &held) == 0 && ::stat(lock.c_str(), &named) == 0 &&
        held.st_ino == named.st_ino && held.st_dev == named.st_dev)
      return;
    ::close(lock_);
    lock_ = -1;
  }
  throw CheckpointError(lock +
                        ": the lock file keeps being replaced; is another process "
                        "making this run?");
}

RunCheckpoint::~RunCheckpoint() {
  if (lock_ < 0) return;
  // Unlinked while held, so no other process can have locked the same name meanwhile.
  std::error_code ec;
  std::filesystem::remove(run_path_ + ".lock", ec);  // a SIGKILL leaves it: harmless
  ::close(lock_);
}

bool RunCheckpoint::exists() const { return std::filesystem::exists(state_path_); }

std::string RunCheckpoint::copyPath(std::uint64_t k) const {
  return fmt::format("{}.checkpoint-{}.h5md", run_path_, k);
}

void RunCheckpoint::removeCopiesExcept(const std::string& keep) const {
  const std::filesystem::path run(run_path_);
  const std::filesystem::path dir = run.parent_path().empty() ? "." : run.parent_path();
  const std::string prefix = run.filename().string();
  const std::string kept = keep.empty() ? "" : std::filesystem::path(keep).filename().string();
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!files::isCheckpointCopyOf(name, prefix) || name == kept) continue;
    std::filesystem::remove(entry.path(), ec);
  }
}

std::uint64_t RunCheckpoint::save(const EdSimulation& sim, H5mdWriter* writer,
                                  const NamedCheckpointables& observers, CheckpointLedger ledger) {
  ++ledger.checkpoints;
  const std::string copy = writer ? copyPath(ledger.checkpoints) : "";
  try {
    if (writer) writer->checkpoint(copy);
    h5::AtomicFile out(state_path_);
    h5::File& f = out.file();
    f.writeStringAttribute("/", "format", kFormat);
    f.writeStringAttribute("/", "identity", identity_);
    f.writeStringAttribute("/", "run_copy",
                           copy.empty() ? "" : std::filesystem::path(copy).filename().string());
    f.writeAttribute<double>("/", "initial_energy", ledger.initial_energy);
    f.writeAttribute<double>("/", "wall_seconds", ledger.wall_seconds);
    f.writeAttribute<double>("/", "cpu_seconds", ledger.cpu_seconds);
    f.writeAttribute<std::uint64_t>("/", "checkpoints", ledger.checkpoints);
    writeEngineState(f, "/engine", sim.state());
    for (const auto& [name, observer] : observers) observer->saveState(f, "/observers/" + name);
    out.commit();
  } catch (const std::exception& e) {
    std::error_code ec;
    if (!copy.empty()) std::filesystem::remove(copy, ec);
    throw CheckpointError(
        fmt::format("{}: cannot write checkpoint {} ({}); the previous one is kept", state_path_,
                    ledger.checkpoints, e.what()));
  }
  // Only now is the new pair complete; the older copies can go.
  removeCopiesExcept(copy);
  return ledger.checkpoints;
}

LoadedCheckpoint RunCheckpoint::load(const NamedCheckpointables& observers) const {
  try {
    const h5::File f = h5::File::openReadOnly(state_path_);
    if (!f.hasAttribute("/", "format") || f.readStringAttribute("/", "format") != kFormat)
      throw CheckpointError(state_path_ + ": not a granwave checkpoint (no format \"" +
                            std::string(kFormat) + "\")");
    if (f.readStringAttribute("/", "identity") != identity_)
      throw CheckpointError(
          state_path_ +
          ": saved by a run of another scene, options or build of granwave; remove it (and " +
          run_path_ + ".checkpoint-*.h5md) to start the run afresh");
    LoadedCheckpoint out;
    out.ledger.initial_energy = f.readAttribute<double>("/", "initial_energy");
    out.ledger.wall_seconds = f.readAttribute<double>("/", "wall_seconds");
    out.ledger.cpu_seconds = f.readAttribute<double>("/", "cpu_seconds");
    out.ledger.checkpoints = f.readAttribute<std::uint64_t>("/", "checkpoints");
    const std::string copy = f.readStringAttribute("/", "run_copy");
    if (!copy.empty()) {
      const std::filesystem::path dir = std::filesystem::path(state_path_).parent_path();
      out.run_copy = (dir / copy).string();
      if (!std::filesystem::exists(out.run_copy))
        throw CheckpointError(state_path_ + ": its copy of the run file, " + out.run_copy +
                              ", is missing; remove the checkpoint to start afresh");
    }
    out.engine = readEngineState(f, "/engine");
    for (const auto& [name, observer] : observers) observer->restoreState(f, "/observers/" + name);
    return out;
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::exception& e) {
    // HDF5 errors name the file; the engine's and observers' consistency checks do not.
    throw CheckpointError(state_path_ + ": damaged checkpoint (" + e.what() + "); remove it and " +
                          run_path_ + ".checkpoint-*.h5md to start the run afresh");
  }
}

void RunCheckpoint::remove() const {
  std::error_code ec;
  std::filesystem::remove(state_path_, ec);
  removeCopiesExcept("");
}

std::pair<double, double> checkpointedCost(const std::string& run_path) {
  try {
    const h5::File f = h5::File::openReadOnly(run_path + ".checkpoint");
    return {f.readAttribute<double>("/", "wall_seconds"),
            f.readAttribute<double>("/", "cpu_seconds")};
  } catch (const h5::H5Error&) {
    return {0.0, 0.0};
  }
}

}  // namespace granwave
