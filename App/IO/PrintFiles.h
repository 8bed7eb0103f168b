// Writing printable bodies in the formats slicers and CAD read: binary STL, 3MF, STEP.
#pragma once

#include "Printable/PrintInPlace.h"

#include <string>
#include <vector>

namespace fabguide::io {

/// Triangulates and writes binary STL; `bodies` as one file.
void writeStl(const std::vector<printable::Body>& bodies, const std::string& path);
/// A 3MF package: the bodies as one object (3D/3dmodel.model), its lowest corner at the origin, and for
/// PrusaSlicer one named part per body (Metadata/Slic3r_PE_model.config).
void write3mf(const std::vector<printable::Body>& bodies, const std::string& path);
/// STEP AP214, the exact solids.
void writeStep(const std::vector<printable::Body>& bodies, const std::string& path);

/// The assembly and each body in each format into `folder`: assembly.stl/.3mf/.step and
/// <body>.stl/.3mf/.step, renamed into place together (within the caller's OutputBatch when one is open).
/// Returns the paths written.
std::vector<std::string> writePrintFiles(const printable::Printable& printable, const std::string& folder);

}  // namespace fabguide::io
