// Reading JSON model files with errors that name the file, the position and the field.
#pragma once

#include "Geometry/Interval.h"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fabguide::io {

/// Malformed input: the message names the offending field, e.g. "parts[2].width: must be > 0".
class FormatError : public std::runtime_error {
public:
    /// A field refused: "field: why", `field` its path in the document ("parts[2].width").
    FormatError(const std::string& field, const std::string& why);
    /// A field refused, the name it holds said after it: "field ('subject'): why".
    FormatError(const std::string& field, const std::string& subject, const std::string& why);
    /// A mistake that names no field.
    explicit FormatError(const std::string& message) : std::runtime_error(message) {}
    /// The path of the field refused, or "" when the error names none.
    const std::string& field() const { return field_; }
    /// The same error, read from the file at `path`: the file named before the message.
    FormatError inFile(const std::string& path) const;

private:
    std::string field_;
};

/// A number as people write it in messages: 0, -3, 0.25.
std::string show(double x);

/// The largest magnitude a number in a model file may have, and the deepest nesting: 10^6 is 1 km in mm, and
/// beyond it lie only typing slips and hostile files that would overflow the solvers' arithmetic. Layout
/// files also hold areas in mm², up to kLargestArea.
constexpr double kLargestNumber = 1e6, kLargestArea = 1e12;
constexpr int kDeepestNesting = 32;

/// Throws FormatError naming the first number beyond ±largest (e.g. "parts[3].outline[2][0]: 1e12 is beyond
/// ±1000000") or the first value nested deeper than kDeepestNesting. Every reader of a model calls it first.
void checkNumbers(const nlohmann::json& document, double largest = kLargestNumber);

/// The document in `path`; FormatError naming the file when it is missing, not JSON, or fails checkNumbers.
nlohmann::json readJsonFile(const std::string& path);
void writeJsonFile(const std::string& path, const nlohmann::json& value);

/// A JSON object being read, with the path that names it in error messages.
class Fields {
public:
    Fields(const nlohmann::json& object, std::string path);

    /// A number; `fallback` when absent, else a FormatError. Checks `minimum` (inclusive) if given.
    double number(const std::string& key, std::optional<double> fallback = std::nullopt,
                  std::optional<double> minimum = std::nullopt) const;
    /// A number that must be strictly positive.
    double positive(const std::string& key) const;
    int integer(const std::string& key, std::optional<int> fallback = std::nullopt) const;
    std::string text(const std::string& key, std::optional<std::string> fallback = std::nullopt) const;
    /// true or false; `fallback` when absent.
    bool flag(const std::string& key, bool fallback) const;
    /// A document's "format" (when given) must be `format` and its "version" (when given) `version`; its
    /// "description" (when given) is free text.
    void header(const std::string& format, int version) const;
    /// A vector [x, y, z].
    Eigen::Vector3d vector3(const std::string& key) const;
    /// A box by its corners "min" and "max" ([x, y, z] each, max beyond min along every axis): the formats'
    /// one way of writing a box.
    BoxSides box() const;
    /// The value at key as written, null when absent: for what the reader of that value checks itself.
    const nlohmann::json& value(const std::string& key) const;
    /// The array at key (required unless `optional`, then empty when absent).
    const nlohmann::json& array(const std::string& key, bool optional = false) const;
    /// Refuses a key not in `known` (a misspelt "kerff" would otherwise be ignored without a word), naming it
    /// and the known key it is closest to.
    void only(const std::vector<std::string>& known) const;
    /// Once the object is read: refuses a key its reader did not ask for nor list in `alsoKnown` (keys
    /// FabGuide writes for people, such as a solve's report), as only() does. What is read is what is known.
    void noOthers(const std::vector<std::string>& alsoKnown = {}) const;
    std::string pathOf(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    bool has(const std::string& key) const;

private:
    const nlohmann::json* find(const std::string& key) const;
    /// Throws FormatError: `key` is missing (`what` is required), or misspelt as a key one letter off.
    [[noreturn]] void missing(const std::string& key, const std::string& what) const;
    const nlohmann::json& object_;
    std::string path_;
    mutable std::vector<std::string> asked_;  ///< every key read or looked for, for noOthers
};

}  // namespace fabguide::io
