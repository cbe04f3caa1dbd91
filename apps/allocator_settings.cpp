#include "apps/allocator_settings.hpp"

#include <cstdlib>

#ifdef ARGUS_WITH_MIMALLOC
#include <mimalloc.h>
#endif

namespace argus::apps {

void keep_freed_memory_mapped() {
#ifdef ARGUS_WITH_MIMALLOC
  if (std::getenv("MIMALLOC_ALLOW_DECOMMIT") == nullptr)
    mi_option_disable(mi_option_allow_decommit);
#endif
}

}  // namespace argus::apps
