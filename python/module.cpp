// The extension module `argus._argus`, imported by python/argus/__init__.py in a Python process.

#include "python/bindings.hpp"
#include "python/python_strategy.hpp"

PYBIND11_MODULE(_argus, m) {
  argus::pybridge::bind_all(m);
  // The interpreter runs already: python:MODULE:CLASS is imported in it.
  argus::pybridge::serve_python_strategies({});
}
