// What every fuzz harness shares: the input parsed as JSON (anything else is not a model file), and the
// errors a reader or the core may end with by design. Any other exception, a crash or a sanitizer report is
// a bug the fuzzer reports.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>

namespace fabguide::fuzz {

inline std::optional<nlohmann::json> parsed(const uint8_t* data, size_t size)
{
    nlohmann::json document = nlohmann::json::parse(data, data + size, nullptr, false);
    if (document.is_discarded())
        return std::nullopt;
    return document;
}

/// Runs f, letting through only the named errors of the readers (FormatError) and the core
/// (std::invalid_argument for bad settings, std::runtime_error such as PackingError).
template <typename F>
void runNamed(F&& f)
{
    try {
        f();
    } catch (const std::invalid_argument&) {
    } catch (const std::runtime_error&) {
    }
}

/// A harness's body: `f` on the input parsed as JSON, its named errors let through; anything else is a
/// finding.
template <typename F>
int onDocument(const uint8_t* data, size_t size, F&& f)
{
    if (const auto document = parsed(data, size))
        runNamed([&] { f(*document); });
    return 0;
}

}  // namespace fabguide::fuzz
