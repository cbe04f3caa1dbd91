#pragma once

/// Forward declarations of the argus_config types, for headers that only pass them around.

namespace argus::config {

struct run_settings;
struct world_settings;
struct plan_point;
struct degree_range;
struct color_response;
struct imaging_model;
struct camera_settings;
struct network_settings;
struct controller_settings;
struct operator_task;
struct fault;
struct scenario;
struct problem;
struct value_bounds;

enum class dropout_kind;
enum class camera_type;
enum class conflict_solver;
enum class fault_kind;

class scenario_error;

}  // namespace argus::config
