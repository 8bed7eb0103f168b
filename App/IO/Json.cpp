#include "IO/Json.h"

#include "Core/Text.h"
#include "IO/Output.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fabguide::io {

std::string show(double x)
{
    std::ostringstream out;
    out << x;
    return out.str();
}

FormatError::FormatError(const std::string& field, const std::string& why)
    : std::runtime_error(field + ": " + why), field_(field)
{
}

FormatError::FormatError(const std::string& field, const std::string& subject, const std::string& why)
    : std::runtime_error(field + " ('" + subject + "'): " + why), field_(field)
{
}

FormatError FormatError::inFile(const std::string& path) const
{
    FormatError error(path + ": " + what());
    error.field_ = field_;
    return error;
}

namespace {

/// The first value of a document that checkNumbers refuses: its path from the value searched (".parts[3].x",
/// "" for that value itself) and why; `tooDeep` when it is nested too deep.
struct Refusal {
    std::string path, why;
    bool tooDeep = false;
};

/// The first value of `value` (at `depth` in its document) that checkNumbers refuses; nothing when none.
std::optional<Refusal> refused(const nlohmann::json& value, double largest, int depth)
{
    if (depth > kDeepestNesting)
        return Refusal{"", "nested more than " + std::to_string(kDeepestNesting) + " levels deep", true};
    if (value.is_number()) {
        const double x = value.get<double>();
        if (std::abs(x) <= largest)
            return std::nullopt;
        return Refusal{"", value.dump() + " is beyond ±" + std::to_string(static_cast<long long>(largest))};
    }
    // A path past a few levels only buries the message: a too-deep value is named by where its nesting
    // starts.
    const auto within = [&](const std::string& step, Refusal r) {
        if (!(depth > 3 && r.tooDeep && r.path.empty()))
            r.path = step + r.path;
        return r;
    };
    if (value.is_array())
        for (size_t k = 0; k < value.size(); ++k)
            if (std::optional<Refusal> r = refused(value[k], largest, depth + 1))
                return within("[" + std::to_string(k) + "]", *r);
    if (value.is_object())
        for (const auto& item : value.items())
            if (std::optional<Refusal> r = refused(item.value(), largest, depth + 1))
                return within("." + item.key(), *r);
    return std::nullopt;
}

}  // namespace

void checkNumbers(const nlohmann::json& document, double largest)
{
    if (const std::optional<Refusal> r = refused(document, largest, 0))
        throw FormatError(!r->path.empty() && r->path[0] == '.' ? r->path.substr(1) : "document" + r->path,
                          r->why);
}

nlohmann::json readJsonFile(const std::string& path)
{
    completeInterruptedRuns(
        std::filesystem::path(path).parent_path().string());  // a set cut short read whole
    std::ifstream in(path);
    if (!in)
        throw FormatError(path + ": cannot open file");
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw FormatError(path + ": not valid JSON (byte " + std::to_string(e.byte) + ")");
    } catch (const nlohmann::json::exception& e) {  // e.g. 1e999: "number overflow"
        std::string what = e.what();
        throw FormatError(path + ": not valid JSON (" + what.substr(what.find(']') + 2) + ")");
    }
    try {
        checkNumbers(document);
    } catch (const FormatError& e) {
        throw e.inFile(path);
    }
    return document;
}

void writeJsonFile(const std::string& path, const nlohmann::json& value)
{
    writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << value.dump(2) << "\n";
        if (!out.flush())
            throw FormatError(path + ": cannot write file");
    });
}

Fields::Fields(const nlohmann::json& object, std::string path) : object_(object), path_(std::move(path))
{
    if (!object_.is_object())
        throw FormatError(path_.empty() ? "document" : path_, "must be a JSON object");
}

const nlohmann::json* Fields::find(const std::string& key) const
{
    has(key);
    auto it = object_.find(key);
    return it == object_.end() || it->is_null() ? nullptr : &*it;
}

double Fields::number(const std::string& key, std::optional<double> fallback,
                      std::optional<double> minimum) const
{
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!fallback)
            missing(key, "a number");
        return *fallback;
    }
    if (!value->is_number() || !std::isfinite(value->get<double>()))
        throw FormatError(pathOf(key), "must be a number, got " + value->dump());
    const double x = value->get<double>();
    if (minimum && x < *minimum)
        throw FormatError(pathOf(key), "must be at least " + show(*minimum) + ", got " + show(x));
    return x;
}

double Fields::positive(const std::string& key) const
{
    const double x = number(key);
    if (!(x > 0))
        throw FormatError(pathOf(key), "must be greater than 0, got " + show(x));
    return x;
}

int Fields::integer(const std::string& key, std::optional<int> fallback) const
{
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!fallback)
            missing(key, "a whole number");
        return *fallback;
    }
    if (!value->is_number_integer() || std::abs(value->get<double>()) > kLargestNumber)
        throw FormatError(pathOf(key), "must be a whole number of at most " + show(kLargestNumber) +
                                           ", got " + value->dump());
    return value->get<int>();
}

std::string Fields::text(const std::string& key, std::optional<std::string> fallback) const
{
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!fallback)
            missing(key, "a string");
        return *fallback;
    }
    if (!value->is_string())
        throw FormatError(pathOf(key), "must be a string, got " + value->dump());
    return value->get<std::string>();
}

bool Fields::flag(const std::string& key, bool fallback) const
{
    const nlohmann::json* value = find(key);
    if (value && !value->is_boolean())
        throw FormatError(pathOf(key), "must be true or false, got " + value->dump());
    return value ? value->get<bool>() : fallback;
}

namespace {

/// The number of single-character edits (insertions, deletions, substitutions) from a to b.
size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

void Fields::only(const std::vector<std::string>& known) const
{
    for (const auto& item : object_.items()) {
        const std::string& key = item.key();
        if (std::find(known.begin(), known.end(), key) != known.end())
            continue;
        const auto closest = std::min_element(known.begin(), known.end(), [&](const auto& a, const auto& b) {
            return editDistance(key, a) < editDistance(key, b);
        });
        throw FormatError(pathOf(key),
                          "no such key" + (closest != known.end() && editDistance(key, *closest) <= 2
                                               ? "; did you mean \"" + *closest + "\"?"
                                               : " (known: " + joined(known) + ")"));
    }
}

void Fields::missing(const std::string& key, const std::string& what) const
{
    // A key one letter off that no reader asked for is the required one misspelt ("coverring", "maxx").
    for (const auto& item : object_.items())
        if (item.key().size() >= 4 && editDistance(item.key(), key) == 1 &&
            std::find(asked_.begin(), asked_.end(), item.key()) == asked_.end())
            throw FormatError(pathOf(item.key()), "no such key; did you mean \"" + key + "\"?");
    throw FormatError(pathOf(key), "missing (" + what + " is required)");
}

bool Fields::has(const std::string& key) const
{
    if (std::find(asked_.begin(), asked_.end(), key) == asked_.end())
        asked_.push_back(key);
    return object_.contains(key);
}

void Fields::noOthers(const std::vector<std::string>& alsoKnown) const
{
    std::vector<std::string> known = asked_;
    known.insert(known.end(), alsoKnown.begin(), alsoKnown.end());
    only(known);
}

void Fields::header(const std::string& format, int version) const
{
    if (text("format", format) != format)
        throw FormatError(pathOf("format"), "expected \"" + format + "\", got \"" + text("format") + "\"");
    if (const int given = integer("version", version); given != version)
        throw FormatError(pathOf("version"), "this FabGuide reads version " + std::to_string(version) +
                                                 ", the file is version " + std::to_string(given));
    text("description", "");  // free text for people, in any document
}

const nlohmann::json& Fields::value(const std::string& key) const
{
    static const nlohmann::json absent;
    const nlohmann::json* found = find(key);
    return found ? *found : absent;
}

Eigen::Vector3d Fields::vector3(const std::string& key) const
{
    const nlohmann::json& value = array(key);
    if (value.size() != 3 || !value[0].is_number() || !value[1].is_number() || !value[2].is_number())
        throw FormatError(pathOf(key), "must be [x, y, z], got " + value.dump());
    return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

BoxSides Fields::box() const
{
    const Eigen::Vector3d low = vector3("min"), high = vector3("max");
    for (int a = 0; a < 3; ++a)
        if (!(high[a] > low[a]))
            throw FormatError(pathOf("max"), "must exceed min along every axis");
    return {low.x(), high.x(), low.y(), high.y(), low.z(), high.z()};
}

const nlohmann::json& Fields::array(const std::string& key, bool optional) const
{
    static const nlohmann::json empty = nlohmann::json::array();
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!optional)
            missing(key, "an array");
        return empty;
    }
    if (!value->is_array())
        throw FormatError(pathOf(key), "must be an array, got " + value->dump());
    return *value;
}

}  // namespace fabguide::io
