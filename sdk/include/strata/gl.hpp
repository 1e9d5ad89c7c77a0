#pragma once
// The one place the OpenGL function loader is named. libepoxy resolves entry points lazily for whichever
// context is current (EGL or GLX), so no explicit load step is needed; swapping loaders touches this file.
#include <epoxy/gl.h>
