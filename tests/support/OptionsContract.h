#pragma once
// What every config::Options struct must satisfy, checked the same way for each (a generic,
// data-driven test; tests/config/test_all_options.cpp runs it over every struct):
//  - its defaults are valid;
//  - saveToConfigFile() writes every declared key, each with a comment, and nothing else;
//  - defaults -> save -> load gives the same saved text;
//  - each key binds a field of its own: changing one key's value in the file changes that key
//    and no other in the re-saved text (no two keys on one field, no key that reads nothing);
//  - all keys changed at once load and save back unchanged.
#include <toposlam/config/Options.h>

#include <functional>
#include <memory>
#include <string>

namespace toposlam::test {

using OptionsFactory = std::function<std::unique_ptr<config::Options>()>;

/// Runs the checks above with gtest assertions; `make` returns a default-constructed struct.
void expectOptionsContract(const OptionsFactory& make, const std::string& section);

/// `options` saved into [section], as text.
std::string savedText(const config::Options& options, const std::string& section);

}  // namespace toposlam::test
