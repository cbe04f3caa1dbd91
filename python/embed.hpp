#pragma once

namespace argus::pybridge {

/// Lets the `argus` executable run strategies named python:MODULE:CLASS: the interpreter
/// starts when a scenario first names one, with the `argus` package importable.
void enable_embedded_python();

}  // namespace argus::pybridge
