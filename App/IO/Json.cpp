#include "IO/Json.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace fabguide::io {

std::string show(double x)
{
    std::ostringstream out;
    out << x;
    return out.str();
}

nlohmann::json readJsonFile(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw FormatError(path + ": cannot open file");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw FormatError(path + ": not valid JSON (byte " + std::to_string(e.byte) + ")");
    }
}

void writeJsonFile(const std::string& path, const nlohmann::json& value)
{
    std::ofstream out(path);
    out << value.dump(2) << "\n";
    if (!out)
        throw FormatError(path + ": cannot write file");
}

Fields::Fields(const nlohmann::json& object, std::string path) : object_(object), path_(std::move(path))
{
    if (!object_.is_object())
        throw FormatError((path_.empty() ? std::string("document") : path_) + ": must be a JSON object");
}

const nlohmann::json* Fields::find(const std::string& key) const
{
    auto it = object_.find(key);
    return it == object_.end() || it->is_null() ? nullptr : &*it;
}

double Fields::number(const std::string& key, std::optional<double> fallback,
                      std::optional<double> minimum) const
{
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!fallback)
            throw FormatError(pathOf(key) + ": missing (a number is required)");
        return *fallback;
    }
    if (!value->is_number() || !std::isfinite(value->get<double>()))
        throw FormatError(pathOf(key) + ": must be a number, got " + value->dump());
    const double x = value->get<double>();
    if (minimum && x < *minimum)
        throw FormatError(pathOf(key) + ": must be at least " + show(*minimum) + ", got " + show(x));
    return x;
}

double Fields::positive(const std::string& key) const
{
    const double x = number(key);
    if (!(x > 0))
        throw FormatError(pathOf(key) + ": must be greater than 0, got " + show(x));
    return x;
}

int Fields::integer(const std::string& key, std::optional<int> fallback) const
{
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!fallback)
            throw FormatError(pathOf(key) + ": missing (a whole number is required)");
        return *fallback;
    }
    if (!value->is_number_integer())
        throw FormatError(pathOf(key) + ": must be a whole number, got " + value->dump());
    return value->get<int>();
}

std::string Fields::text(const std::string& key, std::optional<std::string> fallback) const
{
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!fallback)
            throw FormatError(pathOf(key) + ": missing (a string is required)");
        return *fallback;
    }
    if (!value->is_string())
        throw FormatError(pathOf(key) + ": must be a string, got " + value->dump());
    return value->get<std::string>();
}

bool Fields::flag(const std::string& key, bool fallback) const
{
    const nlohmann::json* value = find(key);
    if (value && !value->is_boolean())
        throw FormatError(pathOf(key) + ": must be true or false, got " + value->dump());
    return value ? value->get<bool>() : fallback;
}

void Fields::header(const std::string& format, int version) const
{
    if (text("format", format) != format)
        throw FormatError("format: expected \"" + format + "\", got \"" + text("format") + "\"");
    if (const int given = integer("version", version); given != version)
        throw FormatError("version: this FabGuide reads version " + std::to_string(version) +
                          ", the file is version " + std::to_string(given));
}

Eigen::Vector3d Fields::vector3(const std::string& key) const
{
    const nlohmann::json& value = array(key);
    if (value.size() != 3 || !value[0].is_number() || !value[1].is_number() || !value[2].is_number())
        throw FormatError(pathOf(key) + ": must be [x, y, z], got " + value.dump());
    return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

const nlohmann::json& Fields::array(const std::string& key, bool optional) const
{
    static const nlohmann::json empty = nlohmann::json::array();
    const nlohmann::json* value = find(key);
    if (!value) {
        if (!optional)
            throw FormatError(pathOf(key) + ": missing (an array is required)");
        return empty;
    }
    if (!value->is_array())
        throw FormatError(pathOf(key) + ": must be an array, got " + value->dump());
    return *value;
}

}  // namespace fabguide::io
