#include "serve/workers/JobKind.h"

namespace figment::serve {

std::string_view jobKindName(JobKind kind) {
  return kind == JobKind::kFit ? "fit" : "render";
}

std::optional<JobKind> jobKindNamed(std::string_view name) {
  if (name == "render") return JobKind::kRender;
  if (name == "fit") return JobKind::kFit;
  return std::nullopt;
}

std::string WorkRequest::digestText() const {
  return kind == JobKind::kFit ? "fit?" + canonical : canonical;
}

}  // namespace figment::serve
