#include <dlfcn.h>
#include <toposlam/mapping/IcpEngine.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace toposlam::mapping {

namespace {

using IcpEngineFactory = IcpEngine* (*)(const mrpt::config::CConfigFileBase&);

/// libtoposlam-mrptslam.so beside the library this function is in (build tree and install
/// tree alike), loaded once and kept for the life of the process.
IcpEngineFactory icpEngineFactory() {
    static const IcpEngineFactory factory = [] {
        Dl_info self{};
        if (dladdr(reinterpret_cast<void*>(&loadIcpEngine), &self) == 0 || !self.dli_fname)
            throw std::runtime_error("engine = icp: cannot tell where libtoposlam-mapping is");
        const std::string path =
            (std::filesystem::path(self.dli_fname).parent_path() / "libtoposlam-mrptslam.so")
                .string();
        void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!library)
            throw std::runtime_error(  // dlerror() names the file
                "engine = icp needs libtoposlam-mrptslam.so beside libtoposlam-mapping.so: " +
                std::string(dlerror()));
        void* entry = dlsym(library, kIcpEngineFactorySymbol);
        if (!entry)
            throw std::runtime_error(path + " has no " + kIcpEngineFactorySymbol + ": " +
                                     dlerror());
        return reinterpret_cast<IcpEngineFactory>(entry);
    }();
    return factory;
}

}  // namespace

std::unique_ptr<IcpEngine> loadIcpEngine(const mrpt::config::CConfigFileBase& ini) {
    return std::unique_ptr<IcpEngine>(icpEngineFactory()(ini));
}

}  // namespace toposlam::mapping
