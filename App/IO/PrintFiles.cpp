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
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Vec.hxx>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

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

/// A body's triangles moved by `by`, its vertices shared where its faces meet, outward-facing. A node within
/// 1e-5 mm of one taken already is that one: a slot meeting a face 8e-6 mm from its edge leaves a tiny edge
/// whose nodes round apart in a file's floats, and the mesh was not closed (generated seeds 7548, 7747); a
/// triangle left with two corners alike is dropped.
struct Mesh {
    std::vector<gp_Pnt> vertices;
    std::vector<std::array<int, 3>> triangles;
};

Mesh meshOf(const TopoDS_Shape& body, const gp_Vec& by)
{
    constexpr double weld = 1e-5;
    Mesh mesh;
    std::map<std::array<long long, 3>, std::vector<int>> cells;  // the vertices in each weld-sized cube
    const auto vertex = [&](const gp_Pnt& p) {
        const std::array<long long, 3> cell = {std::llround(std::floor(p.X() / weld)),
                                               std::llround(std::floor(p.Y() / weld)),
                                               std::llround(std::floor(p.Z() / weld))};
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz)
                    if (const auto near = cells.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
                        near != cells.end())
                        for (int v : near->second)
                            if (mesh.vertices[v].Distance(p) <= weld)
                                return v;
        cells[cell].push_back(static_cast<int>(mesh.vertices.size()));
        mesh.vertices.push_back(p);
        return static_cast<int>(mesh.vertices.size()) - 1;
    };
    for (TopExp_Explorer e(body, TopAbs_FACE); e.More(); e.Next()) {
        const TopoDS_Face& face = TopoDS::Face(e.Current());
        TopLoc_Location location;
        const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
        if (triangulation.IsNull())
            continue;
        std::vector<int> ids(triangulation->NbNodes() + 1);
        for (int n = 1; n <= triangulation->NbNodes(); ++n)
            ids[n] = vertex(triangulation->Node(n).Transformed(location.Transformation()).Translated(by));
        for (int t = 1; t <= triangulation->NbTriangles(); ++t) {
            int a, b, c;
            triangulation->Triangle(t).Get(a, b, c);
            if (face.Orientation() == TopAbs_REVERSED)
                std::swap(b, c);
            if (ids[a] != ids[b] && ids[b] != ids[c] && ids[c] != ids[a])
                mesh.triangles.push_back({ids[a], ids[b], ids[c]});
        }
    }
    return mesh;
}

/// The bodies' triangles as one mesh moved by `by` (meshOf each): 3MF <vertex> and <triangle> elements;
/// returns how many triangles each body has.
std::vector<int> meshXml(const std::vector<printable::Body>& bodies, const gp_Vec& by,
                         std::ostringstream& vertices, std::ostringstream& triangles)
{
    std::vector<int> counts;
    int first = 0;  // the body's first vertex
    for (const printable::Body& body : bodies) {
        const Mesh mesh = meshOf(body.shape, by);
        for (const gp_Pnt& p : mesh.vertices) {
            char text[120];
            std::snprintf(text, sizeof text, "<vertex x=\"%.6f\" y=\"%.6f\" z=\"%.6f\"/>", p.X(), p.Y(),
                          p.Z());
            vertices << text;
        }
        for (const std::array<int, 3>& t : mesh.triangles)
            triangles << "<triangle v1=\"" << first + t[0] << "\" v2=\"" << first + t[1] << "\" v3=\""
                      << first + t[2] << "\"/>";
        first += static_cast<int>(mesh.vertices.size());
        counts.push_back(static_cast<int>(mesh.triangles.size()));
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
    meshed(bodies);  // the bodies' faces triangulated in place, which meshOf reads
    std::vector<Mesh> meshes;
    std::uint32_t count = 0;
    for (const printable::Body& body : bodies) {
        meshes.push_back(meshOf(body.shape, gp_Vec()));
        count += static_cast<std::uint32_t>(meshes.back().triangles.size());
    }
    writeAtomically(path, [&](const std::string& file) {
        std::ofstream out(file, std::ios::binary);
        char header[80] = "binary STL written by FabGuide";
        out.write(header, sizeof header);
        out.write(reinterpret_cast<const char*>(&count), sizeof count);  // little-endian, as STL wants
        for (const Mesh& mesh : meshes)
            for (const std::array<int, 3>& t : mesh.triangles) {
                const gp_Pnt &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
                gp_Vec normal = gp_Vec(a, b).Crossed(gp_Vec(a, c));
                if (normal.Magnitude() > 0)
                    normal.Normalize();
                const float values[12] = {float(normal.X()), float(normal.Y()), float(normal.Z()),
                                          float(a.X()),      float(a.Y()),      float(a.Z()),
                                          float(b.X()),      float(b.Y()),      float(b.Z()),
                                          float(c.X()),      float(c.Y()),      float(c.Z())};
                const std::uint16_t attributes = 0;
                out.write(reinterpret_cast<const char*>(values), sizeof values);
                out.write(reinterpret_cast<const char*>(&attributes), sizeof attributes);
            }
        if (!out)
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
