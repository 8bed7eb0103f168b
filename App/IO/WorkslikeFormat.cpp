#include "IO/WorkslikeFormat.h"

#include "Core/Text.h"
#include "Function/Cover.h"
#include "Function/FitInside.h"
#include "Function/Pose.h"
#include "Function/Support.h"
#include "Geometry/Interval.h"
#include "IO/Json.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace fabguide::io {

namespace {

using function::Face;
using function::Side;

const std::map<std::string, int> kSizes{{"width", 0}, {"depth", 1}, {"height", 2}};  // along x, y, z

std::string at(const std::string& array, size_t i)
{
    return array + "[" + std::to_string(i) + "]";
}

int cuboidNamed(const function::Model& model, const std::string& name, const std::string& path)
{
    for (size_t c = 0; c < model.cuboids.size(); ++c)
        if (model.cuboids[c].name == name)
            return static_cast<int>(c);
    throw FormatError(path, "no cuboid named '" + name + "'");
}

/// "cuboid.side" or "cuboid.width|depth|height" as an expression (a size is right − left), times `factor`.
function::Expression quantity(const function::Model& model, const nlohmann::json& value,
                              const std::string& path, double factor = 1)
{
    if (!value.is_string())
        throw FormatError(path,
                          "must be a quantity such as \"lid.top\" or \"lid.height\", got " + value.dump());
    const std::string text = value.get<std::string>();
    const size_t dot = text.rfind('.');
    if (dot == std::string::npos)
        throw FormatError(path, "\"" + text + "\" must be cuboid.side or cuboid.size");
    const int c = cuboidNamed(model, text.substr(0, dot), path);
    const std::string what = text.substr(dot + 1);
    for (int k = 0; k < 6; ++k)
        if (what == function::sideName(static_cast<Side>(k)))
            return {{{factor, Face{c, static_cast<Side>(k)}}}, 0};
    if (auto size = kSizes.find(what); size != kSizes.end())
        return {{{factor, Face{c, static_cast<Side>(2 * size->second + 1)}},
                 {-factor, Face{c, static_cast<Side>(2 * size->second)}}},
                0};
    throw FormatError(path,
                      "\"" + what + "\" is not left, right, near, far, bottom, top, width, depth or height");
}

Face face(const function::Model& model, const nlohmann::json& value, const std::string& path)
{
    const function::Expression e = quantity(model, value, path);
    if (e.terms.size() != 1)
        throw FormatError(path, "must name a face such as \"lid.top\", not a size");
    return e.terms[0].second;
}

/// A side of a geometric relationship: one quantity or a list summed, each a string or {"quantity", "times"};
/// `normal` the list of {"quantity", "times"}.
function::Expression sum(const function::Model& model, const nlohmann::json& value, const std::string& path,
                         nlohmann::json& normal)
{
    function::Expression total;
    const nlohmann::json items = value.is_array() ? value : nlohmann::json::array({value});
    normal = nlohmann::json::array();
    for (size_t k = 0; k < items.size(); ++k) {
        const std::string here = value.is_array() ? at(path, k) : path;
        const nlohmann::json term = items[k].is_object() ? items[k] : nlohmann::json{{"quantity", items[k]}};
        const Fields fields(term, here);
        const double times = fields.number("times", 1.0);
        const function::Expression e = quantity(
            model, fields.value("quantity"), items[k].is_object() ? fields.pathOf("quantity") : here, times);
        fields.noOthers();
        total.terms.insert(total.terms.end(), e.terms.begin(), e.terms.end());
        normal.push_back({{"quantity", term["quantity"]}, {"times", times}});
    }
    return total;
}

std::array<double, 3> point(const Fields& fields, const std::string& key)
{
    const Eigen::Vector3d p = fields.vector3(key);
    return {p.x(), p.y(), p.z()};
}

/// A cuboid's sizes as the user drew them, before any solve: three positive numbers.
std::array<double, 3> drawnSizes(const Fields& cuboid)
{
    const std::array<double, 3> sizes = point(cuboid, "drawn");
    for (double size : sizes)
        if (!(size > 0))
            throw FormatError(cuboid.pathOf("drawn"), "sizes must be more than 0");
    return sizes;
}

int partNamed(const function::Model& model, const std::string& name, const std::string& path)
{
    for (size_t p = 0; p < model.parts.size(); ++p)
        if (model.parts[p].name == name)
            return static_cast<int>(p);
    throw FormatError(path, "no part named '" + name + "'");
}

const char* kAxes[] = {"x", "y", "z"};

/// What `solve` finishes in seconds (a 3,000-joint chain took 104 s), far beyond any product (a few
/// hundred cuboids, joints a few deep, a few configurations): cuboids, joints in a chain to the ground,
/// cuboids times configurations (each configuration's motion is sampled at up to 63 poses).
constexpr size_t kMostCuboids = 10000, kDeepestChain = 64, kMostPosedCuboids = 100000;

/// An axis named "x", "y" or "z" as 0, 1, 2; else an error at `path` saying what it must be (`shape`).
int axisNamed(const nlohmann::json& value, const std::string& path, const char* shape)
{
    const auto axis = value.is_string()
                          ? std::find(std::begin(kAxes), std::end(kAxes), value.get<std::string>())
                          : std::end(kAxes);
    if (axis == std::end(kAxes))
        throw FormatError(path, std::string("must be ") + shape + ", got " + value.dump());
    return static_cast<int>(axis - std::begin(kAxes));
}

/// A double pivot's pivot: ["cuboid.side", [x, y, z]], a point on that face of a cuboid of `part`; returns
/// the face and the point's in-plane offsets from the cuboid's low corner.
std::pair<Face, std::array<double, 2>> readPivot(const function::Model& model, const Fields& j,
                                                 const std::string& key, int part)
{
    const nlohmann::json& pivot = j.array(key);
    const std::string path = j.pathOf(key);
    if (pivot.size() != 2 || !pivot[1].is_array() || pivot[1].size() != 3)
        throw FormatError(path, "must be [\"cuboid.side\", [x, y, z]], a point on that face");
    const Face f = face(model, pivot[0], path + "[0]");
    const auto& cuboids = model.parts[part].cuboids;
    if (std::find(cuboids.begin(), cuboids.end(), f.cuboid) == cuboids.end())
        throw FormatError(path + "[0]", "'" + function::faceName(model, f) + "' is not a face of part '" +
                                            model.parts[part].name + "'");
    const int n = function::axisOf(f.side);
    std::array<double, 2> offsets{};
    for (int k = 0; k < 2; ++k) {
        const int a = (n + 1 + k) % 3;
        if (!pivot[1][a].is_number())
            throw FormatError(path + "[1]", "must be [x, y, z]");
        const auto& c = model.cuboids[f.cuboid].coordinates;
        offsets[k] = pivot[1][a].get<double>() - c[2 * a];
        if (offsets[k] < -1e-6 || offsets[k] > c[2 * a + 1] - c[2 * a] + 1e-6)
            throw FormatError(path + "[1]", "the point lies off " + function::faceName(model, f));
    }
    return {f, offsets};
}

void readPivots(const function::Model& model, const Fields& j, function::Joint& joint)
{
    if (joint.base < 0)
        throw FormatError(j.pathOf("base"), "a double pivot links its part to a base part");
    std::tie(joint.pivotFace, joint.pivot) = readPivot(model, j, "pivot", joint.part);
    std::tie(joint.basePivotFace, joint.basePivot) = readPivot(model, j, "base_pivot", joint.base);
    if (function::axisOf(joint.pivotFace.side) != function::axisOf(joint.basePivotFace.side))
        throw FormatError(j.pathOf("base_pivot"), "the pivots' faces must be parallel (coplanar)");
}

/// A pivot as written: [face, [x, y, z]] at the solved coordinates.
nlohmann::json pivotJson(const function::Model& model, const Face& f, const std::array<double, 2>& offsets)
{
    const auto& c = model.cuboids[f.cuboid].coordinates;
    const int n = function::axisOf(f.side);
    std::array<double, 3> point{};
    point[n] = c[static_cast<int>(f.side)];
    for (int k = 0; k < 2; ++k) {
        const int a = (n + 1 + k) % 3;
        point[a] = c[2 * a] + offsets[k];
    }
    return {function::faceName(model, f), point};
}

void readJoint(function::Model& model, const nlohmann::json& json, const std::string& path)
{
    const Fields j(json, path);
    function::Joint joint;
    joint.name = j.text("name");
    for (const function::Joint& other : model.joints)
        if (other.name == joint.name)
            throw FormatError(j.pathOf("name"), "'" + joint.name + "' is used twice");
    joint.part = partNamed(model, j.text("part"), j.pathOf("part"));
    const std::string type = j.text("type");
    for (const function::Joint& other : model.joints)  // parallel links: double pivots posed alike
        if (other.part == joint.part &&
            !(type == "double_pivot" && other.type == function::Joint::Type::DoublePivot))
            throw FormatError(j.pathOf("part"), "'" + model.parts[joint.part].name +
                                                    "' is already moved by joint '" + other.name + "'");
    if (j.has("base")) {
        joint.base = partNamed(model, j.text("base"), j.pathOf("base"));
        if (joint.base == joint.part)
            throw FormatError(j.pathOf("base"), "a part cannot hang on itself");
    }
    const auto known = std::find_if(function::kJointKinds.begin(), function::kJointKinds.end(),
                                    [&](const function::JointKind& k) { return k.name == type; });
    if (known == function::kJointKinds.end()) {
        throw FormatError(
            j.pathOf("type"),
            "\"" + type + "\" is not a joint this FabGuide knows (" +
                joined(function::kJointKinds, [](const function::JointKind& k) { return k.name; }) + ")");
    }
    joint.type = known->type;
    if (joint.type == function::Joint::Type::Fixed && joint.base < 0)
        throw FormatError(j.pathOf("base"), "a fixed joint holds its part to a base part");
    if (joint.type == function::Joint::Type::DoublePivot)
        readPivots(model, j, joint);
    if (joint.turns()) {
        const nlohmann::json& edge = j.array("edge");
        if (edge.size() != 2)
            throw FormatError(j.pathOf("edge"), "must name the two faces that meet at the hinge's edge");
        joint.edgeA = face(model, edge[0], at(j.pathOf("edge"), 0));
        joint.edgeB = face(model, edge[1], at(j.pathOf("edge"), 1));
        const auto& cuboids = model.parts[joint.part].cuboids;
        if (joint.edgeA.cuboid != joint.edgeB.cuboid ||
            std::find(cuboids.begin(), cuboids.end(), joint.edgeA.cuboid) == cuboids.end())
            throw FormatError(j.pathOf("edge"), "both faces must belong to one cuboid of part '" +
                                                    model.parts[joint.part].name + "'");
        if (static_cast<int>(joint.edgeA.side) / 2 == static_cast<int>(joint.edgeB.side) / 2)
            throw FormatError(j.pathOf("edge"), "the two faces are parallel, they meet at no edge");
    }
    if (joint.slides()) {
        joint.axis = axisNamed(j.text("axis"), j.pathOf("axis"), "\"x\", \"y\" or \"z\"");
    }
    j.noOthers();
    model.joints.push_back(joint);
}

void readConfiguration(function::Model& model, const nlohmann::json& json, const std::string& path)
{
    const Fields c(json, path);
    function::Configuration configuration;
    configuration.name = c.text("name");
    for (const function::Configuration& other : model.configurations)
        if (other.name == configuration.name)
            throw FormatError(c.pathOf("name"), "'" + configuration.name + "' is used twice");
    if (!c.has("poses") || !json["poses"].is_object())
        throw FormatError(c.pathOf("poses"), "must map joint names to angles (degrees) or offsets (mm)");
    for (const auto& item : json["poses"].items()) {
        const std::string& name = item.key();
        const nlohmann::json& value = item.value();
        const std::string here = c.pathOf("poses") + "." + name;
        const auto joint = std::find_if(model.joints.begin(), model.joints.end(),
                                        [&](const function::Joint& j) { return j.name == name; });
        if (joint == model.joints.end())
            throw FormatError(here, "no joint named '" + name + "'");
        function::JointPose pose{static_cast<int>(joint - model.joints.begin())};
        if (joint->type == function::Joint::Type::Fixed)
            throw FormatError(here, "joint '" + name + "' is fixed: it does not move, pose its base's joint");
        if (joint->type == function::Joint::Type::SlidingHinge) {
            const Fields both(value, here);
            pose.angle = both.number("angle");
            pose.offset = both.number("offset");
            both.noOthers();
        } else if (joint->type == function::Joint::Type::DoublePivot) {
            const Fields turn(value, here);
            pose.angle = turn.number("angle");
            pose.pole = point(turn, "pole");
            turn.noOthers();
        } else if (!value.is_number()) {
            throw FormatError(here, "must be a number, got " + value.dump());
        } else {
            (joint->turns() ? pose.angle : pose.offset) = value.get<double>();
        }
        if (std::abs(pose.angle) > 360)  // a configuration turns a joint once at most
            throw FormatError(here, "an angle of at most 360 degrees either way, got " + show(pose.angle));
        configuration.poses.push_back(pose);
    }
    c.noOthers();
    model.configurations.push_back(configuration);
    const int k = static_cast<int>(model.configurations.size()) - 1;
    for (const function::JointPose& a : configuration.poses) {
        const function::Joint& first = model.joints[a.joint];
        if (first.type != function::Joint::Type::DoublePivot)
            continue;
        // Its base stands still here (stage 2 places pivots against a fixed base).
        if (const int carrier = function::jointMovingIn(model, first.base, k); carrier >= 0)
            throw FormatError(c.pathOf("poses"),
                              "'" + first.name + "' needs its base '" + model.parts[first.base].name +
                                  "' to stand still, but '" + model.joints[carrier].name + "' moves it");
        // Double pivots that move one part (parallel links) take it to one place.
        for (size_t j = 0; j < model.joints.size(); ++j) {
            const function::Joint& other = model.joints[j];
            if (static_cast<int>(j) == a.joint || other.part != first.part ||
                other.type != function::Joint::Type::DoublePivot)
                continue;
            const function::JointPose* b = function::poseOf(model, static_cast<int>(j), k);
            if (!b || b->angle != a.angle || b->pole != a.pole)
                throw FormatError(c.pathOf("poses"), "'" + first.name + "' and '" + other.name +
                                                         "' move one part and must be posed alike");
        }
    }
}

/// An array of axes ["x", "z"] as 0, 2.
std::vector<int> axisList(const Fields& fields, const std::string& key)
{
    const nlohmann::json& names = fields.array(key);
    std::vector<int> axes;
    for (size_t k = 0; k < names.size(); ++k)
        axes.push_back(axisNamed(names[k], at(fields.pathOf(key), k), "\"x\", \"y\" or \"z\""));
    return axes;
}

std::vector<int> partList(const function::Model& model, const Fields& r, const std::string& key)
{
    const nlohmann::json& names = r.array(key);
    if (names.empty())
        throw FormatError(r.pathOf(key), "name at least one part");
    std::vector<int> parts;
    for (size_t k = 0; k < names.size(); ++k) {
        if (!names[k].is_string())
            throw FormatError(at(r.pathOf(key), k), "must be a part name, got " + names[k].dump());
        parts.push_back(partNamed(model, names[k].get<std::string>(), at(r.pathOf(key), k)));
    }
    return parts;
}

/// Why part `part` cannot take part in the relationship, said where it names the part: "relationships[2].
/// covering[1] ('right door'): why", that path its field.
FormatError unlinked(const function::Model& model, const Fields& r, std::initializer_list<const char*> keys,
                     int part, const std::string& why)
{
    const std::string& name = model.parts[part].name;
    for (const char* key : keys) {
        const nlohmann::json& names = r.array(key);
        for (size_t k = 0; k < names.size(); ++k)
            if (names[k] == name)
                return FormatError(at(r.pathOf(key), k), name, why);
    }
    return FormatError("'" + name + "': " + why);
}

/// A relationship's "pairs" [["a.side", "b.side"], …] as face pairs; `shape` is what each must look like.
std::vector<std::pair<Face, Face>> facePairs(const function::Model& model, const Fields& r, const char* shape)
{
    const nlohmann::json& pairs = r.array("pairs");
    std::vector<std::pair<Face, Face>> out;
    for (size_t k = 0; k < pairs.size(); ++k) {
        const std::string here = at(r.pathOf("pairs"), k);
        if (!pairs[k].is_array() || pairs[k].size() != 2)
            throw FormatError(here, std::string("must be ") + shape);
        out.push_back({face(model, pairs[k][0], here + "[0]"), face(model, pairs[k][1], here + "[1]")});
    }
    return out;
}

/// Support (thesis 4.2.3): "pairs" [["leg.top", "top.bottom"], …] as given, or inferred (4.3.3) when absent.
function::Support readSupport(const function::Model& model, const Fields& r, const std::string& name,
                              int configuration, nlohmann::json& normal)
{
    function::Support s{
        name, partList(model, r, "supporting"), partList(model, r, "supported"), {}, configuration, {}};
    const double distance = r.number("distance", 100.0, 0.0);  // how far apart inferred pairs may be
    normal["distance"] = distance;
    if (!r.has("pairs")) {
        function::InferredSupport inferred =
            function::inferSupport(model, s.supporting, s.supported, configuration, distance);
        if (!inferred.unlinked.empty())
            throw unlinked(model, r, {"supporting", "supported"}, inferred.unlinked.front(),
                           "no bottom face of a supported part lies above a top face of a supporting one");
        s.pairs = std::move(inferred.pairs);
        s.notes = std::move(inferred.notes);
        return s;
    }
    const auto pairs = facePairs(model, r, "[\"supporting.top\", \"supported.bottom\"]");
    for (size_t k = 0; k < pairs.size(); ++k) {
        const auto& [top, bottom] = pairs[k];
        if (top.side != Side::Top || bottom.side != Side::Bottom)
            throw FormatError(at(r.pathOf("pairs"), k),
                              "a supporting top face rests under a supported bottom face");
        s.pairs.push_back({top.cuboid, bottom.cuboid});
    }
    return s;
}

/// Fit inside (thesis 4.2.2): "apart" [["drawer 1", "z", "drawer 2"], …] (cuboids in that order along the
/// axis) and "just" as axes ["x", …] or face pairs [["drawer 1.left", "chest.left"], …]; inferred when absent
/// (4.3.2).
function::FitInside readFitInside(const function::Model& model, const Fields& r, const std::string& name,
                                  int configuration, nlohmann::json& normal)
{
    function::FitInside f;
    f.name = name;
    f.inner = partList(model, r, "inner");
    f.enclosing = partNamed(model, r.text("enclosing"), r.pathOf("enclosing"));
    f.configuration = configuration;
    if (std::find(f.inner.begin(), f.inner.end(), f.enclosing) != f.inner.end())
        throw FormatError(r.pathOf("enclosing"), "a part cannot fit inside itself");
    if (r.has("cavity")) {
        f.cavity = cuboidNamed(model, r.text("cavity"), r.pathOf("cavity"));
        const auto& own = model.parts[f.enclosing].cuboids;
        if (!model.cuboids[f.cavity].cavity() || std::find(own.begin(), own.end(), f.cavity) == own.end())
            throw FormatError(r.pathOf("cavity"), "'" + r.text("cavity") + "' is not a cavity of part '" +
                                                      model.parts[f.enclosing].name + "'");
    }
    const nlohmann::json& portion = r.array("portion", true);
    normal["portion"] = portion;
    for (size_t k = 0; k < portion.size(); ++k) {
        const std::string here = at(r.pathOf("portion"), k);
        if (!portion[k].is_string())
            throw FormatError(here, "must name a cuboid of an inner part");
        const int c = cuboidNamed(model, portion[k].get<std::string>(), here);
        if (std::none_of(f.inner.begin(), f.inner.end(), [&](int p) {
                return std::find(model.parts[p].cuboids.begin(), model.parts[p].cuboids.end(), c) !=
                       model.parts[p].cuboids.end();
            }))
            throw FormatError(here, "'" + model.cuboids[c].name + "' is not a cuboid of an inner part");
        f.portion.push_back(c);
    }
    if (!r.has("apart")) {
        f.apart = function::inferApart(model, f.inner, configuration);
    } else {
        const nlohmann::json& apart = r.array("apart");
        for (size_t k = 0; k < apart.size(); ++k) {
            const std::string here = at(r.pathOf("apart"), k);
            if (!apart[k].is_array() || apart[k].size() != 3 || !apart[k][1].is_string())
                throw FormatError(here, "must be [\"cuboid\", \"x|y|z\", \"cuboid\"]");
            const auto axis = std::find(std::begin(kAxes), std::end(kAxes), apart[k][1].get<std::string>());
            if (axis == std::end(kAxes) || !apart[k][0].is_string() || !apart[k][2].is_string())
                throw FormatError(here, "must be [\"cuboid\", \"x|y|z\", \"cuboid\"]");
            f.apart.push_back({cuboidNamed(model, apart[k][0].get<std::string>(), here + "[0]"),
                               cuboidNamed(model, apart[k][2].get<std::string>(), here + "[2]"),
                               static_cast<int>(axis - std::begin(kAxes))});
        }
    }
    const nlohmann::json& just = r.array("just", true);
    normal["just"] = just;
    std::vector<int> axes;
    for (size_t k = 0; k < just.size(); ++k) {
        const std::string here = at(r.pathOf("just"), k);
        if (just[k].is_string()) {
            axes.push_back(
                axisNamed(just[k], here, "\"x\", \"y\", \"z\", a pair of faces or {\"part\", \"axes\"}"));
        } else if (just[k].is_object()) {  // one inner part just fits on its own
            const Fields each(just[k], here);
            const int part = partNamed(model, each.text("part"), each.pathOf("part"));
            if (std::find(f.inner.begin(), f.inner.end(), part) == f.inner.end())
                throw FormatError(each.pathOf("part"), "'" + each.text("part") + "' is not an inner part");
            const auto inferred = function::inferJust(model, f, {part}, axisList(each, "axes"));
            each.noOthers();
            f.just.insert(f.just.end(), inferred.begin(), inferred.end());
        } else if (just[k].is_array() && just[k].size() == 2) {
            f.just.push_back({face(model, just[k][0], here + "[0]"), face(model, just[k][1], here + "[1]")});
        } else {
            throw FormatError(here, "must be \"x\", \"y\", \"z\" or a pair of faces");
        }
    }
    const auto inferred = function::inferJust(model, f, f.inner, axes);
    f.just.insert(f.just.end(), inferred.begin(), inferred.end());
    return f;
}

/// Cover (thesis 4.2.1): "pairs" [["lid.bottom", "body.top"], …] (covering face, covered face) as given, or
/// inferred (4.3.1) when absent; faces of one component of the graph must be parallel.
function::Cover readCover(const function::Model& model, const Fields& r, const std::string& name,
                          int configuration, nlohmann::json& normal)
{
    function::Cover c{name, partList(model, r, "covering"), partList(model, r, "covered"),
                      {},   r.flag("just", false),          configuration,
                      {},   r.number("distance", 5.0, 0.0)};
    normal["just"] = c.just;
    normal["distance"] = c.distance;
    if (!r.has("pairs")) {
        const double distance = c.distance;
        function::InferredCover inferred =
            function::inferCover(model, c.covering, c.covered, configuration, distance);
        if (!inferred.unlinked.empty())
            throw unlinked(model, r, {"covering", "covered"}, inferred.unlinked.front(),
                           "no face of it faces a face of the other side, overlapping it by half");
        c.pairs = std::move(inferred.pairs);
        c.notes = std::move(inferred.notes);
        return c;
    }
    c.pairs = facePairs(model, r, "[\"covering face\", \"covered face\"]");
    for (const function::CoverComponent& component : function::components(c.pairs))
        for (const auto* faces : {&component.covering, &component.covered})
            for (const Face& f : *faces)
                if (static_cast<int>(f.side) / 2 != static_cast<int>(component.covering.front().side) / 2)
                    throw FormatError(r.pathOf("pairs"),
                                      function::faceName(model, f) + " and " +
                                          function::faceName(model, component.covering.front()) +
                                          " are linked but not parallel");
    return c;
}

int configurationNamed(const function::Model& model, const Fields& r)
{
    if (!r.has("configuration"))
        return -1;
    const std::string name = r.text("configuration");
    for (size_t c = 0; c < model.configurations.size(); ++c)
        if (model.configurations[c].name == name)
            return static_cast<int>(c);
    throw FormatError(r.pathOf("configuration"), "no configuration named '" + name + "'");
}

/// The relationship kind a type names (function::kConflictKinds), or a FormatError listing those there are.
function::ConflictKind relationshipKind(const std::string& type, const std::string& path)
{
    std::string known;
    for (const function::ConflictKindName& k : function::kConflictKinds)
        if (k.relationship) {
            if (type == k.name)
                return k.kind;
            known += (known.empty() ? "" : ", ") + std::string(k.name);
        }
    throw FormatError(path, "\"" + type + "\" is not a relationship this FabGuide knows (" + known + ")");
}

void readRelationship(function::Model& model, const nlohmann::json& json, const std::string& path,
                      nlohmann::json& normal)
{
    const Fields r(json, path);
    const std::string type = r.text("type"), name = r.text("name");
    const int configuration = configurationNamed(model, r);
    const auto named = [&](const auto& list) {
        return std::any_of(list.begin(), list.end(),
                           [&](const auto& relationship) { return relationship.name == name; });
    };
    if (named(model.flush) || named(model.geometric) || named(model.support) || named(model.fitInside) ||
        named(model.cover))
        throw FormatError(r.pathOf("name"), "'" + name + "' is used twice");
    model.relationshipOrder.push_back(name);
    using K = function::ConflictKind;
    switch (relationshipKind(type, r.pathOf("type"))) {
        case K::Flush: {
            const nlohmann::json& faces = r.array("faces");
            if (faces.size() != 2)
                throw FormatError(r.pathOf("faces"), "must name two faces");
            model.flush.push_back({name, face(model, faces[0], at(r.pathOf("faces"), 0)),
                                   face(model, faces[1], at(r.pathOf("faces"), 1)), configuration});
            break;
        }
        case K::Geometric: {
            const std::string relation = r.text("relation", "equal");
            if (relation != "equal" && relation != "at_most")
                throw FormatError(r.pathOf("relation"),
                                  "must be \"equal\" or \"at_most\", got \"" + relation + "\"");
            if (!r.has("left") || !r.has("right"))
                throw FormatError(r.pathOf(r.has("left") ? "right" : "left"), "missing");
            function::Geometric g{name,
                                  relation == "equal" ? function::Geometric::Relation::Equal
                                                      : function::Geometric::Relation::AtMost,
                                  sum(model, json["left"], r.pathOf("left"), normal["left"]),
                                  sum(model, json["right"], r.pathOf("right"), normal["right"])};
            g.right.constant = r.number("offset", 0.0);
            normal["relation"] = relation;
            normal["offset"] = g.right.constant;
            g.configuration = configuration;
            model.geometric.push_back(g);
            break;
        }
        case K::FitInside:
            model.fitInside.push_back(readFitInside(model, r, name, configuration, normal));
            break;
        case K::Support:
            model.support.push_back(readSupport(model, r, name, configuration, normal));
            break;
        case K::Cover:
            model.cover.push_back(readCover(model, r, name, configuration, normal));
            break;
        default:  // not a relationship: relationshipKind refused it
            break;
    }
    r.noOthers();
}

/// The solid cuboid of the part that a cavity overlaps most (thesis 4.1.1: cavities are cut from solids).
int solidAround(const function::Model& model, const function::Part& part, const function::Cuboid& cavity,
                const std::string& path)
{
    int best = -1;
    double most = 0;
    for (int s : part.cuboids) {
        const function::Cuboid& solid = model.cuboids[s];
        if (solid.cavity() || &solid == &cavity)
            continue;
        double volume = 1;
        for (int a = 0; a < 3; ++a)
            volume *= std::max(0.0, overlapOf(along(solid.coordinates, a), along(cavity.coordinates, a)));
        if (volume > most) {
            most = volume;
            best = s;
        }
    }
    if (best < 0)
        throw FormatError(
            path, "cavity '" + cavity.name + "' lies outside every solid cuboid of part '" + part.name + "'");
    return best;
}

nlohmann::json partNames(const function::Model& model, const std::vector<int>& parts)
{
    nlohmann::json names = nlohmann::json::array();
    for (int p : parts)
        names.push_back(model.parts[p].name);
    return names;
}

/// Relationships (written kind by kind) put back in the order they were read; those not read (made by
/// code) follow, kind by kind.
void inReadingOrder(nlohmann::json& relationships, const std::vector<std::string>& order)
{
    const auto rank = [&](const nlohmann::json& r) {
        return std::find(order.begin(), order.end(), r["name"].get<std::string>()) - order.begin();
    };
    std::stable_sort(relationships.begin(), relationships.end(),
                     [&](const nlohmann::json& a, const nlohmann::json& b) { return rank(a) < rank(b); });
}

}  // namespace

WorkslikeDocument readWorkslikeDocument(const nlohmann::json& document)
{
    checkNumbers(document);
    const Fields root(document, "");
    root.header("fabguide.workslike", kWorkslikeFormatVersion);
    function::Model model;
    nlohmann::json normal = document;
    normal["format"] = "fabguide.workslike";
    normal["version"] = kWorkslikeFormatVersion;
    normal["minimum_size"] = model.minimumSize = root.number("minimum_size", 1.0, 0.0);
    normal["minimum_wall"] = model.minimumWall = root.number("minimum_wall", 1.0, 0.0);
    const nlohmann::json& parts = root.array("parts");
    for (size_t p = 0; p < parts.size(); ++p) {
        const Fields part(parts[p], at("parts", p));
        function::Part built{part.text("name"), {}};
        const nlohmann::json& cuboids = part.array("cuboids");
        if (cuboids.empty())
            throw FormatError(part.pathOf("cuboids"), "a part needs at least one cuboid");
        for (size_t c = 0; c < cuboids.size(); ++c) {
            const Fields cuboid(cuboids[c], at(part.pathOf("cuboids"), c));
            const std::string name =
                cuboid.text("name", built.name + (cuboids.size() > 1 ? std::to_string(c + 1) : ""));
            nlohmann::json& written = normal["parts"][p]["cuboids"][c];
            written["name"] = name;
            for (const function::Cuboid& other : model.cuboids)
                if (other.name == name)
                    throw FormatError(cuboid.pathOf("name"), "'" + name + "' is used twice");
            built.cuboids.push_back(static_cast<int>(model.cuboids.size()));
            model.cuboids.push_back({name, cuboid.box()});
            if (cuboid.has("drawn"))
                model.cuboids.back().drawn = drawnSizes(cuboid);
            if (written["cavity"] = cuboid.flag("cavity", false); written["cavity"]) {
                if (c == 0)
                    throw FormatError(cuboid.pathOf("cavity"),
                                      "a part's first cuboid is solid (cavities are cut from solids)");
                model.cuboids.back().within =
                    solidAround(model, built, model.cuboids.back(), cuboid.pathOf("min"));
            }
            cuboid.noOthers();
        }
        part.noOthers();
        model.parts.push_back(built);
        if (model.cuboids.size() > kMostCuboids)
            throw FormatError(part.pathOf("cuboids"),
                              "more than " + std::to_string(kMostCuboids) +
                                  " cuboids in the model; FabGuide solves up to that");
    }
    const nlohmann::json& joints = root.array("joints", true);
    normal["joints"] = joints;
    for (size_t j = 0; j < joints.size(); ++j)
        readJoint(model, joints[j], at("joints", j));
    for (size_t j = 0; j < model.joints.size(); ++j) {  // every chain of joints ends on the ground
        int base = model.joints[j].base;
        for (size_t step = 0; base >= 0; ++step) {
            if (step == model.joints.size())
                throw FormatError(at("joints", j) + ".base", "the joints' bases go round in a circle");
            if (step == kDeepestChain)
                throw FormatError(at("joints", j) + ".base",
                                  "more than " + std::to_string(kDeepestChain) +
                                      " joints in a chain to the ground; FabGuide solves chains up to that");
            const int carrier = function::jointMoving(model, base);
            base = carrier < 0 ? -1 : model.joints[carrier].base;
        }
    }

    const nlohmann::json& configurations = root.array("configurations", true);
    normal["configurations"] = configurations;
    for (size_t c = 0; c < configurations.size(); ++c)
        readConfiguration(model, configurations[c], at("configurations", c));
    if (model.cuboids.size() * configurations.size() > kMostPosedCuboids)
        throw FormatError("configurations",
                          std::to_string(configurations.size()) + " configurations of " +
                              std::to_string(model.cuboids.size()) + " cuboids; FabGuide solves up to " +
                              std::to_string(kMostPosedCuboids) + " cuboids times configurations");
    const nlohmann::json& relationships = root.array("relationships", true);
    normal["relationships"] = relationships;
    for (size_t r = 0; r < relationships.size(); ++r)
        readRelationship(model, relationships[r], at("relationships", r), normal["relationships"][r]);
    const nlohmann::json& locks = root.array("locks", true);
    normal["locks"] = locks;
    for (size_t l = 0; l < locks.size(); ++l)
        model.locks.push_back({face(model, locks[l], at("locks", l))});
    root.noOthers({"report"});  // what a solve wrote for people
    return {function::indexed(std::move(model)), std::move(normal)};
}

nlohmann::json workslikeToJson(const function::Model& model, const function::SolveResult* result)
{
    auto expression = [&](const function::Expression& e) {
        nlohmann::json items = nlohmann::json::array();
        for (const auto& [times, f] : e.terms)
            items.push_back({{"quantity", function::faceName(model, f)}, {"times", times}});
        return items;
    };
    nlohmann::json parts = nlohmann::json::array(), relationships = nlohmann::json::array(),
                   locks = nlohmann::json::array();
    for (const function::Part& part : model.parts) {
        nlohmann::json cuboids = nlohmann::json::array();
        for (int c : part.cuboids) {
            const auto& k = model.cuboids[c].coordinates;
            nlohmann::json cuboid = {
                {"name", model.cuboids[c].name}, {"min", {k[0], k[2], k[4]}}, {"max", {k[1], k[3], k[5]}}};
            if (model.cuboids[c].cavity())
                cuboid["cavity"] = true;
            if (model.cuboids[c].drawn[0] > 0)
                cuboid["drawn"] = model.cuboids[c].drawn;
            cuboids.push_back(cuboid);
        }
        parts.push_back({{"name", part.name}, {"cuboids", cuboids}});
    }
    using K = function::ConflictKind;
    auto inConfiguration = [&](nlohmann::json relationship, int configuration) {
        if (configuration >= 0)
            relationship["configuration"] = model.configurations[configuration].name;
        return relationship;
    };
    for (const function::Flush& f : model.flush)
        relationships.push_back(
            inConfiguration({{"type", function::nameOf(K::Flush)},
                             {"name", f.name},
                             {"faces", {function::faceName(model, f.a), function::faceName(model, f.b)}}},
                            f.configuration));
    for (const function::Geometric& g : model.geometric)
        relationships.push_back(inConfiguration(
            {{"type", function::nameOf(K::Geometric)},
             {"name", g.name},
             {"relation", g.relation == function::Geometric::Relation::Equal ? "equal" : "at_most"},
             {"left", expression(g.left)},
             {"right", expression(g.right)},
             {"offset", g.right.constant}},
            g.configuration));
    for (const function::Support& s : model.support) {
        nlohmann::json pairs = nlohmann::json::array();
        for (const auto& [a, b] : s.pairs)
            pairs.push_back(
                {function::faceName(model, {a, Side::Top}), function::faceName(model, {b, Side::Bottom})});
        relationships.push_back(inConfiguration({{"type", function::nameOf(K::Support)},
                                                 {"name", s.name},
                                                 {"supporting", partNames(model, s.supporting)},
                                                 {"supported", partNames(model, s.supported)},
                                                 {"pairs", pairs}},
                                                s.configuration));
    }
    for (const function::FitInside& f : model.fitInside) {
        nlohmann::json apart = nlohmann::json::array(), just = nlohmann::json::array();

        for (const function::FitInside::Apart& a : f.apart)
            apart.push_back({model.cuboids[a.a].name, kAxes[a.axis], model.cuboids[a.b].name});
        for (const auto& [in, wall] : f.just)
            just.push_back({function::faceName(model, in), function::faceName(model, wall)});
        nlohmann::json fit = {{"type", function::nameOf(K::FitInside)},
                              {"name", f.name},
                              {"inner", partNames(model, f.inner)},
                              {"enclosing", model.parts[f.enclosing].name},
                              {"apart", apart},
                              {"just", just}};
        if (f.cavity >= 0)
            fit["cavity"] = model.cuboids[f.cavity].name;
        if (!f.portion.empty()) {
            fit["portion"] = nlohmann::json::array();
            for (int c : f.portion)
                fit["portion"].push_back(model.cuboids[c].name);
        }
        relationships.push_back(inConfiguration(fit, f.configuration));
    }
    for (const function::Cover& c : model.cover) {
        nlohmann::json pairs = nlohmann::json::array();
        for (const auto& [a, b] : c.pairs)
            pairs.push_back({function::faceName(model, a), function::faceName(model, b)});
        relationships.push_back(inConfiguration({{"type", function::nameOf(K::Cover)},
                                                 {"name", c.name},
                                                 {"covering", partNames(model, c.covering)},
                                                 {"covered", partNames(model, c.covered)},
                                                 {"pairs", pairs},
                                                 {"just", c.just},
                                                 {"distance", c.distance}},
                                                c.configuration));
    }
    inReadingOrder(relationships, model.relationshipOrder);
    for (const function::Lock& lock : model.locks)
        locks.push_back(function::faceName(model, lock.face));
    nlohmann::json joints = nlohmann::json::array(), configurations = nlohmann::json::array();
    for (const function::Joint& j : model.joints) {
        nlohmann::json joint = {{"name", j.name}, {"part", model.parts[j.part].name}};
        joint["type"] = function::kindOf(j.type).name;
        if (j.base >= 0)
            joint["base"] = model.parts[j.base].name;
        if (j.turns())
            joint["edge"] = {function::faceName(model, j.edgeA), function::faceName(model, j.edgeB)};
        if (j.slides())
            joint["axis"] = kAxes[j.axis];
        if (j.type == function::Joint::Type::DoublePivot) {
            joint["pivot"] = pivotJson(model, j.pivotFace, j.pivot);
            joint["base_pivot"] = pivotJson(model, j.basePivotFace, j.basePivot);
        }
        joints.push_back(joint);
    }
    for (const function::Configuration& c : model.configurations) {
        nlohmann::json poses = nlohmann::json::object();
        for (const function::JointPose& pose : c.poses) {
            const function::Joint& j = model.joints[pose.joint];
            poses[j.name] = j.type == function::Joint::Type::SlidingHinge
                                ? nlohmann::json{{"angle", pose.angle}, {"offset", pose.offset}}
                            : j.type == function::Joint::Type::DoublePivot
                                ? nlohmann::json{{"angle", pose.angle}, {"pole", pose.pole}}
                                : nlohmann::json(j.turns() ? pose.angle : pose.offset);
        }
        configurations.push_back({{"name", c.name}, {"poses", poses}});
    }
    nlohmann::json out = {{"format", "fabguide.workslike"},
                          {"version", kWorkslikeFormatVersion},
                          {"minimum_size", model.minimumSize},
                          {"minimum_wall", model.minimumWall},
                          {"parts", parts},
                          {"joints", joints},
                          {"configurations", configurations},
                          {"relationships", relationships},
                          {"locks", locks}};
    if (result) {
        nlohmann::json conflicts = nlohmann::json::array();
        for (const function::Conflict& c : result->conflicts)
            conflicts.push_back(
                {{"kind", function::nameOf(c.kind)}, {"name", c.name}, {"subject", c.subject}});
        out["report"] = {{"solved", result->solved}, {"conflict", result->conflict},
                         {"conflicts", conflicts},   {"violation", result->violation},
                         {"notes", result->notes},   {"parts", result->parts}};
    }
    return out;
}

}  // namespace fabguide::io
