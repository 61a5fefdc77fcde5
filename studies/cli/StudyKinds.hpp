#pragma once
// The study kinds the program knows (docs/studies.md): the one place that names every study,
// so that no study and nothing below the command line depends on another study.
#include <memory>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyFile.hpp"

namespace granwave {

// Reads the study's keys from the file (the caller then rejects unknown ones) and builds its
// scenes; throws StudyError on a bad kind, key or scene.
std::unique_ptr<Study> makeStudy(StudyFile& file);

}  // namespace granwave
