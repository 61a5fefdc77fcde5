// granwave: when does a continuum description of a vibrated granular layer agree with the
// particles? One program, subcommands; errors are reported once, here, in one line.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <new>
#include <string>

#include "files/OutputPath.hpp"
#include "h5/ErrorStack.hpp"
#include "hydro/HydroSimulation.hpp"
#include "particles/EventLoopStall.hpp"
#include "particles/InelasticCollapse.hpp"
#include "scene/SceneParser.hpp"
#include "studies/cli/CommandLineHints.hpp"
#include "studies/cli/ExportCommand.hpp"
#include "studies/cli/FieldsCommand.hpp"
#include "studies/cli/HydroCommand.hpp"
#include "studies/cli/SimulateCommand.hpp"
#include "studies/cli/StudyCommand.hpp"
#include "studies/cli/Version.hpp"
#include "studies/contract/StudyFile.hpp"
#include "studies/particle_run/OutsideFailure.hpp"
#include "studies/run_files/RunCheckpoint.hpp"
#include "studies/runner/ExitCode.hpp"
#include "studies/runner/RemoteWorkers.hpp"
#include "studies/runner/RunScheduler.hpp"

namespace {

// Error messages quote what the user gave (keys, paths, values); a control character among
// them must not break the one-line contract (or move the cursor): it is printed escaped.
std::string oneLine(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    if (c < 0x20 || c == 0x7f) {
      out += c == '\n' ? std::string("\\n") : fmt::format("\\x{:02x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

void printError(const std::string& what) { fmt::print(stderr, "granwave: {}\n", oneLine(what)); }

}  // namespace

int main(int argc, char** argv) {
  granwave::h5::skipLibraryShutdownAtExit();  // h5/ErrorStack.hpp says why
  // Before anything else: MPI may rewrite argc/argv. A no-op outside mpirun.
  granwave::MpiSession mpi(argc, argv);
  CLI::App app{
      "granwave: event-driven simulation and continuum comparison of vibrated granular layers"};
  app.set_version_flag("--version", granwave::versionLine);
  app.require_subcommand(1);
  granwave::SimulateOptions simulate;
  granwave::addSimulateCommand(app, simulate);
  granwave::FieldsOptions fields;
  granwave::addFieldsCommand(app, fields);
  granwave::HydroOptions hydro;
  granwave::addHydroCommand(app, hydro);
  granwave::StudyOptions study;
  granwave::addStudyCommand(app, study);
  granwave::ExportOptions exported;
  granwave::addExportCommand(app, exported);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // One line and the documented code for a bad command line (CLI11's own codes are 100+).
    const std::string hint = granwave::misspeltWordMessage(app, {argv + 1, argv + argc});
    printError(hint.empty() ? std::string(e.what()) + " (see granwave --help)" : hint);
    return granwave::kExitInvalidInput;
  }

  // Under mpirun an error on one rank ends them all (the others may wait for it).
  auto stop = [&mpi](int code) {
    if (mpi.size() > 1) mpi.abort(code);
    return code;
  };
  std::string command_line;
  for (int i = 0; i < argc; ++i) command_line += (i ? " " : "") + std::string(argv[i]);
  try {
    if (app.got_subcommand("simulate")) return granwave::runSimulate(simulate, command_line);
    if (app.got_subcommand("fields")) return granwave::runFields(fields);
    if (app.got_subcommand("hydro")) return granwave::runHydro(hydro);
    if (app.got_subcommand("study")) return granwave::runStudy(study, mpi);
    if (app.got_subcommand("export")) return granwave::runExport(exported);
  } catch (const granwave::StudyInterrupted& e) {
    printError(e.what());
    return stop(granwave::kExitInterrupted);
  } catch (const granwave::StudyError& e) {
    printError(e.what());
    return stop(granwave::kExitInvalidInput);
  } catch (const granwave::files::PathError& e) {
    printError(e.what());
    return stop(granwave::kExitInvalidInput);
  } catch (const std::bad_alloc&) {
    // Not a file error (74): the scene asks for more memory than this machine gives.
    printError("out of memory (a smaller scene, fewer jobs, or a machine with more memory)");
    return stop(granwave::kExitOutOfMemory);
  } catch (const granwave::SceneError& e) {
    printError(e.what());
    return granwave::kExitInvalidInput;
  } catch (const granwave::hydro::HydroFailure& e) {
    printError(std::string("hydrodynamic solver: ") + e.what());
    return granwave::kExitSolverFailure;
  } catch (const granwave::InelasticCollapse& e) {
    printError(e.what());
    return granwave::kExitEngineBreakdown;
  } catch (const granwave::EventLoopStall& e) {
    printError(e.what());
    return granwave::kExitEngineBreakdown;
  } catch (const granwave::CheckpointError& e) {
    printError(e.what());
    return stop(granwave::kExitCheckpointError);
  } catch (const std::exception& e) {
    printError(e.what());
    return stop(granwave::isOutsideFailure(e) ? granwave::kExitFileError : granwave::kExitError);
  }
  return 0;
}
