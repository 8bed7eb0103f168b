#include "IO/PrintFiles.h"

#include "IO/Output.h"

#include "IO/Xml.h"

#include <zip.h>
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Writer.hxx>
#include <StlAPI_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Vec.hxx>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace fabguide::io {

namespace {

/// Triangles finer than a slicer's resolution: 0.02 mm chordal deviation, 0.2 rad.
TopoDS_Shape meshed(const std::vector<printable::Body>& bodies)
{
    BRep_Builder builder;
    TopoDS_Compound all;
    builder.MakeCompound(all);
    for (const printable::Body& b : bodies)
        builder.Add(all, b.shape);
    const BRepMesh_IncrementalMesh meshing(all, 0.02, false, 0.2, true);  // triangulates the faces in place
    return all;
}

/// The bodies' triangles as one mesh moved by `by`, each body's vertices shared where its faces meet,
/// outward-facing: 3MF <vertex> and <triangle> elements; returns how many triangles each body has.
std::vector<int> meshXml(const std::vector<printable::Body>& bodies, const gp_Vec& by,
                         std::ostringstream& vertices, std::ostringstream& triangles)
{
    std::vector<int> counts;
    int first = 0;  // the body's first vertex
    for (const printable::Body& body : bodies) {
        std::map<std::tuple<double, double, double>, int> index;
        int count = 0;
        for (TopExp_Explorer e(body.shape, TopAbs_FACE); e.More(); e.Next()) {
            const TopoDS_Face& face = TopoDS::Face(e.Current());
            TopLoc_Location location;
            const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, location);
            if (mesh.IsNull())
                continue;
            std::vector<int> ids(mesh->NbNodes() + 1);
            for (int n = 1; n <= mesh->NbNodes(); ++n) {
                const gp_Pnt p = mesh->Node(n).Transformed(location.Transformation()).Translated(by);
                const auto key = std::make_tuple(p.X(), p.Y(), p.Z());
                auto [it, added] = index.emplace(key, first + static_cast<int>(index.size()));
                if (added) {
                    char text[120];
                    std::snprintf(text, sizeof text, "<vertex x=\"%.6f\" y=\"%.6f\" z=\"%.6f\"/>", p.X(),
                                  p.Y(), p.Z());
                    vertices << text;
                }
                ids[n] = it->second;
            }
            for (int t = 1; t <= mesh->NbTriangles(); ++t, ++count) {
                int a, b, c;
                mesh->Triangle(t).Get(a, b, c);
                if (face.Orientation() == TopAbs_REVERSED)
                    std::swap(b, c);
                triangles << "<triangle v1=\"" << ids[a] << "\" v2=\"" << ids[b] << "\" v3=\"" << ids[c]
                          << "\"/>";
            }
        }
        first += static_cast<int>(index.size());
        counts.push_back(count);
    }
    return counts;
}

/// PrusaSlicer's description of the object: one part (volume) per body, by its triangles, named.
std::string prusaSlicerConfig(const std::string& name, const std::vector<printable::Body>& bodies,
                              const std::vector<int>& triangles)
{
    std::ostringstream config;
    config << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<config><object id=\"1\" instances_count=\"1\">"
           << "<metadata type=\"object\" key=\"name\" value=\"" << escapeXml(name) << "\"/>";
    int first = 0;
    for (size_t b = 0; b < bodies.size(); first += triangles[b], ++b)
        config << "<volume firstid=\"" << first << "\" lastid=\"" << first + triangles[b] - 1 << "\">"
               << "<metadata type=\"volume\" key=\"name\" value=\"" << escapeXml(bodies[b].name) << "\"/>"
               << "<metadata type=\"volume\" key=\"volume_type\" value=\"ModelPart\"/></volume>";
    config << "</object></config>\n";
    return config.str();
}

std::string lowercase(std::string text)
{
    for (char& c : text)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

/// Whether Windows keeps the name for a device (whatever the extension).
bool reservedOnWindows(const std::string& stem)
{
    static const std::set<std::string> devices{"con", "prn", "aux", "nul"};
    const std::string lower = lowercase(stem);
    return devices.count(lower) ||
           (lower.size() == 4 && (lower.rfind("com", 0) == 0 || lower.rfind("lpt", 0) == 0) &&
            std::isdigit(static_cast<unsigned char>(lower[3])));
}

/// A body's file name stem: its name with '-' for what is not a letter or digit. A body of many parts is
/// named by its first and how many more ("cab-0-0-and-23-more": the joined names of a wall's carcasses passed
/// the 255 bytes a file name may have); a name still longer than 80 is cut there and told apart by its FNV-1a
/// hash.
std::string fileName(const std::string& name)
{
    std::string stem = name;
    const std::string joint = " + ";
    if (stem.size() > 80 && stem.find(joint) != std::string::npos) {
        int more = 0;
        for (size_t at = stem.find(joint); at != std::string::npos; at = stem.find(joint, at + joint.size()))
            ++more;
        stem = stem.substr(0, stem.find(joint)) + " and " + std::to_string(more) + " more";
    }
    std::string out;
    for (char c : stem)
        out += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
    if (out.size() > 80) {
        std::uint32_t hash = 2166136261u;
        for (unsigned char c : name)
            hash = (hash ^ c) * 16777619u;
        char hex[9];
        std::snprintf(hex, sizeof hex, "%08x", hash);
        out = out.substr(0, 71) + "-" + hex;
    }
    return out;
}

}  // namespace

void writeStl(const std::vector<printable::Body>& bodies, const std::string& path)
{
    writeAtomically(path, [&](const std::string& file) {
        StlAPI_Writer writer;
        writer.ASCIIMode() = false;
        if (!writer.Write(meshed(bodies), file.c_str()))
            throw std::runtime_error("cannot write " + path);
    });
}

namespace {

/// A zip package of (name, text) entries in `file` (`path` named in errors).
void writeZip(const std::string (&files)[4][2], const std::string& path, const std::string& file)
{
    int error = 0;
    zip_t* zip = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    if (!zip)
        throw std::runtime_error("cannot write " + path);
    for (const auto& [name, text] : files) {
        zip_source_t* source = zip_source_buffer(zip, text.data(), text.size(), 0);
        if (!source || zip_file_add(zip, name.c_str(), source, ZIP_FL_OVERWRITE) < 0) {
            zip_source_free(source);
            zip_discard(zip);
            throw std::runtime_error("cannot write " + path);
        }
    }
    if (zip_close(zip) < 0)
        throw std::runtime_error("cannot write " + path);
}

}  // namespace

void write3mf(const std::vector<printable::Body>& bodies, const std::string& path)
{
    Bnd_Box bounds;
    BRepBndLib::AddOptimal(meshed(bodies), bounds, true, false);
    double x0 = 0, y0 = 0, z0 = 0, x1, y1, z1;
    if (!bounds.IsVoid())
        bounds.Get(x0, y0, z0, x1, y1, z1);
    // One object, so that slicers keep the bodies where they are, together; its lowest corner at the origin,
    // since slicers take a 3MF's coordinates as where it lies on the bed (in the vertices: PrusaSlicer does
    // not centre an object by a build item's transform).
    const std::string name = bodies.size() == 1 ? bodies.front().name : "assembly";
    std::ostringstream vertices, triangles, model;
    const std::vector<int> counts = meshXml(bodies, gp_Vec(-x0, -y0, -z0), vertices, triangles);
    model
        << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"millimeter\" xml:lang=\"en-US\" "
           "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\"><resources><object id=\"1\" "
           "name=\""
        << escapeXml(name) << "\" type=\"model\"><mesh><vertices>" << vertices.str()
        << "</vertices><triangles>" << triangles.str()
        << "</triangles></mesh></object></resources><build><item objectid=\"1\"/></build>"
        << "</model>\n";
    const std::string files[][2] = {
        {"[Content_Types].xml",
         "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types "
         "xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\"><Default Extension=\"rels\" "
         "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/><Default "
         "Extension=\"model\" "
         "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>\n"},
        {"_rels/.rels",
         "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships "
         "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\"><Relationship "
         "Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
         "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>\n"},
        {"3D/3dmodel.model", model.str()},
        {"Metadata/Slic3r_PE_model.config", prusaSlicerConfig(name, bodies, counts)}};
    writeAtomically(path, [&](const std::string& file) { writeZip(files, path, file); });
}

void writeStep(const std::vector<printable::Body>& bodies, const std::string& path)
{
    BRep_Builder builder;
    TopoDS_Compound all;
    builder.MakeCompound(all);
    for (const printable::Body& b : bodies)
        builder.Add(all, b.shape);
    Message::DefaultMessenger()->RemovePrinters(
        STANDARD_TYPE(Message_PrinterOStream));  // no transfer statistics
    writeAtomically(path, [&](const std::string& file) {
        STEPControl_Writer writer;
        if (writer.Transfer(all, STEPControl_AsIs) != IFSelect_RetDone ||
            writer.Write(file.c_str()) != IFSelect_RetDone)
            throw std::runtime_error("cannot write " + path);
    });
}

std::vector<std::string> writePrintFiles(const printable::Printable& printable, const std::string& folder)
{
    std::filesystem::create_directories(folder);
    OutputBatch batch;  // one set, whether the CLI or FreeCAD's export writes it
    std::vector<std::string> written;
    auto write = [&](const std::vector<printable::Body>& bodies, const std::string& stem) {
        for (const char* extension : {".stl", ".3mf", ".step"}) {
            const std::string path = (std::filesystem::path(folder) / (stem + extension)).string();
            const std::string e = extension;
            if (e == ".stl")
                writeStl(bodies, path);
            else if (e == ".3mf")
                write3mf(bodies, path);
            else
                writeStep(bodies, path);
            written.push_back(path);
        }
    };
    write(printable.bodies, "assembly");
    // Each body's stem its own: "a b" and "a-b" both read a-b, a body named "assembly" or "report" would
    // replace those files, and Windows keeps CON, NUL, COM1... for devices.
    std::set<std::string> taken{"assembly", "report"};
    for (const printable::Body& b : printable.bodies) {
        const std::string stem = fileName(b.name);
        std::string unique = stem;
        for (int k = 2; !taken.insert(lowercase(unique)).second || reservedOnWindows(unique); ++k)
            unique = stem + "-" + std::to_string(k);
        write({b}, unique);
    }
    batch.commit();
    return written;
}

}  // namespace fabguide::io
