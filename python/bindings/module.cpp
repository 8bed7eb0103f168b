// fabguide_core: Python bindings of the C++ core. Plain data crosses this boundary
// (numbers, lists, dicts); FreeCAD document objects in freecad/fabguide call into it.
#include "Bindings.h"
#include "Core/Version.h"

#include <pybind11/stl.h>

namespace py = pybind11;

PYBIND11_MODULE(fabguide_core, m)
{
    m.doc() = "FabGuide core: works-like solving, flat-pack layout and zero-waste exploration";
    m.attr("__version__") = fabguide::version();
    m.def("dependency_versions", &fabguide::dependencyVersions,
          "List of (library, version) compiled into the core.");
    fabguide::bindings::bindMaterial(m);
    fabguide::bindings::bindFunction(m);
    fabguide::bindings::bindPrintable(m);
    fabguide::bindings::bindExplore(m);
}
