// The TopoSLAM plugin for MRPT's own tools. Its work is done by the libraries it links: each
// registers its classes with mrpt-rtti when it is loaded. This symbol lets a user (or a test)
// check that the plugin is the one they expect: `nm -D libtoposlam-plugin.so`.
extern "C" const char* toposlam_plugin_version() {
    return "TopoSLAM 0.1.0";
}
