#pragma once

namespace argus::config {

/// How pedestrians' clothes are coloured. `palette`: the station's palettes, which hold
/// near-twins on purpose (two reds, two navy blues, two greys) so that colour indexing confuses
/// people as the paper says it does; with a hundred people, several share the target's shirt.
/// `varied`: shirt and trousers each of a hue, saturation and value drawn at random, so that two
/// people seldom dress alike: the protocol measured apart from colour indexing's look-alikes.
enum class clothing { palette, varied };

}  // namespace argus::config
