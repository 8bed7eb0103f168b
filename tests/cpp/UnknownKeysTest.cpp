// Every object of every FabGuide format refuses a key it does not know, naming it: a
// generator takes each example and test file, adds a misspelt key to one object at a time, and expects the
// reader to refuse exactly that key. Objects whose keys are names the user chose (a configuration's poses)
// are the only ones that take any key. And every value spoilt is refused with its field given apart from the
// words, as the message names it.
#include "IO/FlatpackFormat.h"
#include "IO/Json.h"
#include "IO/PackFormat.h"
#include "IO/WorkslikeFormat.h"
#include "Layout/Docking.h"
#include "Layout/Pack.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <regex>
#include <string>
#include <vector>

using namespace fabguide;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

/// Objects whose keys the user names: any key is a name there.
const std::regex kNamedKeys(R"(configurations\[\d+\]\.poses|parameters)");

using Reader = std::function<void(const json&)>;

/// `visit(value, path)` for `value` and every value inside it, each with its path as the readers' messages
/// write it ("parts[2].cuboids[0]").
void eachIn(const json& value, const std::string& path,
            const std::function<void(const json&, const std::string&)>& visit)
{
    visit(value, path);
    if (value.is_object())
        for (const auto& item : value.items())
            eachIn(item.value(), path.empty() ? item.key() : path + "." + item.key(), visit);
    else if (value.is_array())
        for (size_t i = 0; i < value.size(); ++i)
            eachIn(value[i], path + "[" + std::to_string(i) + "]", visit);
}

/// The path of every object in `document` but those whose keys the user names.
std::vector<std::string> objectsIn(const json& document)
{
    std::vector<std::string> paths;
    eachIn(document, "", [&](const json& value, const std::string& path) {
        if (value.is_object() && !std::regex_match(path, kNamedKeys))
            paths.push_back(path);
    });
    return paths;
}

/// The path of every value in `document` that is neither an object nor an array.
std::vector<std::string> valuesIn(const json& document)
{
    std::vector<std::string> paths;
    eachIn(document, "", [&](const json& value, const std::string& path) {
        if (!value.is_object() && !value.is_array())
            paths.push_back(path);
    });
    return paths;
}

/// The value at `path` in `document` (a path objectsIn gave).
json& at(json& document, const std::string& path)
{
    json* value = &document;
    const std::regex step(R"(([^.\[\]]+)|\[(\d+)\])");
    for (auto it = std::sregex_iterator(path.begin(), path.end(), step); it != std::sregex_iterator(); ++it)
        value = (*it)[1].matched ? &(*value)[(*it)[1].str()] : &(*value)[std::stoul((*it)[2].str())];
    return *value;
}

/// A key the object does not have, a slip of one of its own keys ("kerf" -> "kerff") when it has any.
std::string misspelt(const json& object)
{
    std::string key = object.empty() ? std::string("colour") : object.begin().key() + "x";
    while (object.contains(key))
        key += "x";
    return key;
}

/// For each object of `document` (which `read` takes), the paths of those that took a misspelt key
/// without a word, or refused it naming something else.
std::vector<std::string> takingUnknownKeys(const json& document, const Reader& read)
{
    std::vector<std::string> taking;
    for (const std::string& path : objectsIn(document)) {
        json spoilt = document;
        json& object = at(spoilt, path);
        const std::string key = misspelt(object);
        object[key] = 1;
        const std::string named = path.empty() ? key : path + "." + key;
        try {
            read(spoilt);
            taking.push_back(named + " (taken)");
        } catch (const io::FormatError& e) {
            if (std::string(e.what()).rfind(named + ": no such key", 0) != 0)
                taking.push_back(named + " (refused as: " + e.what() + ")");
        }
    }
    return taking;
}

std::vector<fs::path> filesEndingIn(const std::string& suffix,
                                    const std::vector<const char*>& folders = {"examples", "tests/data"})
{
    std::vector<fs::path> files;
    for (const char* folder : folders)
        for (const auto& entry : fs::recursive_directory_iterator(fs::path(FABGUIDE_SOURCE_DIR) / folder)) {
            const std::string name = entry.path().filename().string();
            if (name.size() > suffix.size() &&
                name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
                files.push_back(entry.path());
        }
    return files;
}

/// Every file ending in `suffix` (each must read as it is), spoilt object by object.
void expectEveryObjectRefusesUnknownKeys(const std::string& suffix, const Reader& read)
{
    size_t files = 0;
    for (const fs::path& file : filesEndingIn(suffix)) {
        const json document = io::readJsonFile(file.string());
        try {
            read(document);
        } catch (const io::FormatError& e) {
            ADD_FAILURE() << file.filename().string() << " does not read: " << e.what();
            continue;
        }
        ++files;
        for (const std::string& taken : takingUnknownKeys(document, read))
            ADD_FAILURE() << file.filename().string() << ": " << taken;
    }
    EXPECT_GT(files, 0u) << suffix;
}

/// For each value of each example ending in `suffix` made a word or a negative number, the refusals
/// whose field (FormatError::field) is not what their message starts with: "field: " or "field ('name'): ",
/// or, with no field, something other than a path. `named`: the refusals that gave a field.
std::vector<std::string> fieldsNotAsSaid(const std::string& suffix, const Reader& read, size_t& named)
{
    static const std::regex path(R"([A-Za-z_]\w*(\[\d+\]|\.[A-Za-z_]\w*)*: [\s\S]*)");
    std::vector<std::string> wrong;
    const std::vector<const char*> examples{"examples"};  // the test files too took minutes under ASan
    for (const fs::path& file : filesEndingIn(suffix, examples)) {
        const json document = io::readJsonFile(file.string());
        for (const std::string& spoilt : valuesIn(document))
            for (const json& value : {json("x"), json(-1)}) {
                json d = document;
                at(d, spoilt) = value;
                try {
                    read(d);
                } catch (const io::FormatError& e) {
                    const std::string message = e.what(), field = e.field();
                    named += !field.empty();
                    const bool said = field.empty() ? !std::regex_match(message, path)
                                                    : message.rfind(field + ": ", 0) == 0 ||
                                                          message.rfind(field + " ('", 0) == 0;
                    if (!said)
                        wrong.push_back(file.filename().string() + " " + spoilt + " = " + value.dump() +
                                        ": field \"" + field + "\" for \"" + message + "\"");
                }
            }
    }
    return wrong;
}

}  // namespace

TEST(SpoiltValues, EveryRefusalGivesTheFieldItsMessageNames)
{
    const std::vector<std::pair<std::string, Reader>> formats{
        {".pack.json", [](const json& d) { io::readPackProblem(d); }},
        {".workslike.json", [](const json& d) { io::readWorkslike(d); }},
        {".flatpack.json", [](const json& d) { io::readFlatpack(d, io::Satisfied::NotRequired); }}};
    for (const auto& [suffix, read] : formats) {
        size_t named = 0;
        for (const std::string& wrong : fieldsNotAsSaid(suffix, read, named))
            ADD_FAILURE() << wrong;
        EXPECT_GT(named, 50u) << suffix;
    }
}

TEST(UnknownKeys, EveryObjectOfAPackProblemRefusesAKeyItDoesNotKnow)
{
    expectEveryObjectRefusesUnknownKeys(".pack.json", [](const json& d) { io::readPackProblem(d); });
}

TEST(UnknownKeys, EveryObjectOfAWorkslikeModelRefusesAKeyItDoesNotKnow)
{
    expectEveryObjectRefusesUnknownKeys(".workslike.json", [](const json& d) { io::readWorkslike(d); });
}

TEST(UnknownKeys, EveryObjectOfAFlatpackDesignRefusesAKeyItDoesNotKnow)
{
    expectEveryObjectRefusesUnknownKeys(
        ".flatpack.json", [](const json& d) { io::readFlatpack(d, io::Satisfied::NotRequired); });
}

TEST(UnknownKeys, EveryObjectOfALayoutRefusesAKeyItDoesNotKnow)
{
    size_t sawn = 0;
    for (const fs::path& file : filesEndingIn(".pack.json"))
        for (const material::Cuts cuts : {material::Cuts::Free, material::Cuts::Guillotine}) {
            material::PackProblem problem = io::readPackProblem(io::readJsonFile(file.string()));
            problem.settings.cuts = cuts;
            material::OrderingSearchOptions search;
            search.iterations = 0;
            json layout;
            try {
                layout = io::layoutToJson(material::pack(problem, search), problem, io::PartNames::Ids);
            } catch (const std::runtime_error&) {
                continue;  // a job kept to show a part too large, or not rectangular for a saw
            }
            sawn += layout.contains("saw_cuts");
            for (const std::string& taken : takingUnknownKeys(
                     layout, [&](const json& d) { io::readLayout(d, problem, io::PartNames::Ids); }))
                ADD_FAILURE() << file.filename().string() << " laid out: " << taken;
        }
    EXPECT_GT(sawn, 0u) << "no layout with saw cuts was spoilt";
}

TEST(UnknownKeys, AParametricDesignsPartsRefuseWhatTheyDoNotKnowNamingTheField)
{
    const json parts = json::parse(R"([{"id": "side", "quantity": 2, "grain": "z"}, {"id": "bottom"}])");
    const io::ParametricParts read = io::readParametricParts(parts);
    ASSERT_EQ(read.kinds.size(), 2u);
    EXPECT_EQ(read.kinds[0].quantity, 2);
    EXPECT_EQ(read.grainAxes, (std::vector<int>{2, -1}));
    const auto fieldOf = [&](const char* key, const json& value) {
        json spoilt = parts;
        spoilt[1][key] = value;
        try {
            io::readParametricParts(spoilt);
        } catch (const io::FormatError& e) {
            return e.field();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(fieldOf("grain", "Y"), "parts[1].grain");
    EXPECT_EQ(fieldOf("quantity", 0), "parts[1].quantity");
    EXPECT_EQ(fieldOf("quantitty", 1), "parts[1].quantitty");
}

TEST(UnknownKeys, ARequiredKeyMisspeltIsNamedAsMisspeltNotAsMissing)
{
    // A user's "coverring" was reported as "covering: missing", the misspelling left for them to find.
    for (const fs::path& file : filesEndingIn(".workslike.json")) {
        const json document = io::readJsonFile(file.string());
        json spoilt = document;
        json& cuboid = spoilt["parts"][0]["cuboids"][0];
        cuboid["maxx"] = cuboid["max"];
        cuboid.erase("max");
        try {
            io::readWorkslike(spoilt);
            ADD_FAILURE() << file << ": read without its max";
        } catch (const io::FormatError& e) {
            EXPECT_EQ(e.field(), "parts[0].cuboids[0].maxx") << e.what();
            EXPECT_NE(std::string(e.what()).find("did you mean \"max\"?"), std::string::npos) << e.what();
        }
        cuboid.erase("maxx");  // gone altogether: missing
        EXPECT_THROW(
            try { io::readWorkslike(spoilt); } catch (const io::FormatError& e) {
                EXPECT_EQ(e.field(), "parts[0].cuboids[0].max") << e.what();
                throw;
            },
            io::FormatError);
    }
}
