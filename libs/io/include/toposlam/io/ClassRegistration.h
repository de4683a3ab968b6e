#pragma once
// TOPOSLAM_REGISTER_CLASS(Class): registers a serializable class with mrpt-rtti when its library
// is loaded (linked, through the plugin or LD_PRELOAD), so that every MRPT reader of rawlogs and
// simplemaps knows it; IMPLEMENTS_SERIALIZABLE alone does not. Write it right after the class's
// IMPLEMENTS_SERIALIZABLE, in the same source file, with the class's unqualified name.
//
// Why not MRPT_INITIALIZER: runtimeClassId holds a std::function, so it is initialised at run
// time, and only the order of initialisation within one source file is guaranteed. A function
// with the constructor attribute may run before it: clang's builds did, and registered a class
// with no name, which no reader could then find.
#include <mrpt/rtti/CObject.h>

#define TOPOSLAM_REGISTER_CLASS(Class)                      \
    namespace {                                             \
    [[maybe_unused]] const bool Class##Registered =         \
        (mrpt::rtti::registerClass(CLASS_ID(Class)), true); \
    }
