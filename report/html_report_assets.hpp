#pragma once

#include <string_view>

namespace argus::report {

/// The style sheet of report.html.
extern const std::string_view report_style;

/// Runs first: records uncaught errors so the page can report them on #status.
extern const std::string_view report_error_catcher;

/// The event-log filter and the page's self-check (html_report.hpp), run after the body.
extern const std::string_view report_script;

}  // namespace argus::report
