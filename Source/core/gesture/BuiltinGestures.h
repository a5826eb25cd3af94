#pragma once
// The two gestures of [Galluzzo2017], written on the command line as NAME[:key=value,...]:
//   steady:speed=0.05,force=1.0,beta=0.1,seconds=1            bow at constant speed from t = 0 (Schelleng)
//   guettler:acceleration=1.56,force=1.0,beta=0.0899,seconds=0.5  constant acceleration from rest (Guettler)
// Every key is optional (defaults as shown); both also take finger=RATIO (default 1, the open string).
#include <string>

#include "core/gesture/GestureScript.h"

namespace rosin::gesture
{

/// True if `spec` is "steady" or "guettler", alone or followed by ':'.
bool isBuiltinGestureSpec(const std::string& spec);
/// Parses a built-in spec into a one-segment script. Throws GestureError naming the key ("beta", ...).
GestureScript parseBuiltinGesture(const std::string& spec);
/// Usage text listing the built-ins, their keys and defaults; every line starts with `indent`.
std::string builtinGestureHelp(const std::string& indent = "  ");

} // namespace rosin::gesture
