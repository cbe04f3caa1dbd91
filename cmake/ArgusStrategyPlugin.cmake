# argus_add_strategy_plugin(NAME sources...): a strategy plug-in (controller/strategy_plugin.hpp)
# as a MODULE library NAME.so, built with the strategy interface's headers and C++ standard.
# Undefined symbols are left to the `argus` executable that loads it, which exports its own.
function(argus_add_strategy_plugin name)
  add_library(${name} MODULE ${ARGN})
  target_link_libraries(${name} PRIVATE Argus::strategy)
  set_target_properties(${name} PROPERTIES PREFIX "" CXX_VISIBILITY_PRESET hidden)
endfunction()
