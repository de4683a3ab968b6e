#pragma once
// Which options struct reads which section of the files in config_ini/, for the data-driven
// tests (test_all_options.cpp, test_ini_sweep.cpp). A new section or struct goes here.
#include <OptionsContract.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace toposlam::test {

template <class T>
OptionsFactory make(const T& defaults = T()) {
    return [defaults] { return std::unique_ptr<config::Options>(new T(defaults)); };
}

/// Section -> its struct, with the defaults the apps start from.
const std::map<std::string, OptionsFactory>& sectionStructs();

/// The struct of `section`: sectionStructs(), or TopoSLAM's options inside MRPT map
/// definitions (<prefix>_scanFeaturesMap_NN_insertOpts / _likelihoodOpts); empty if none.
OptionsFactory structOfSection(const std::string& section);

/// Sections handed to MRPT classes with MRPT's own key names (CICP, icp-slam's map
/// definitions): not ours to check.
bool isMrptSection(const std::string& section);

/// config_ini/*.ini, sorted.
std::vector<std::string> configFiles();

}  // namespace toposlam::test
