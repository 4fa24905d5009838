#pragma once
// What a worker is asked to do, typed: a render (RenderRequest's canonical text: a PNG or
// GLB back) or a fit (FitRequest's: the size advice's JSON back). The kind travels beside
// the request through the pool's queue and the frames to the worker process, never inside
// its text, so a request's text is only ever parsed as its own kind.

#include <compare>
#include <optional>
#include <string>
#include <string_view>

namespace figment::serve {

enum class JobKind { kRender, kFit };

// "render" or "fit": the kind's frame to a worker.
std::string_view jobKindName(JobKind kind);
// The kind `name` names; nothing for another name.
std::optional<JobKind> jobKindNamed(std::string_view name);

// One request for a worker: its kind and its canonical text. Two equal ones are the same
// work (the pool makes it once).
struct WorkRequest {
  JobKind kind = JobKind::kRender;
  std::string canonical;

  // What the answer's digest (its ETag) starts from: a fit's text after "fit?". A fit was
  // once told from a render by that prefix in its text; its digest keeps it, so the ETags of
  // the same requests are unchanged, and a fit's never equals a render's.
  std::string digestText() const;

  auto operator<=>(const WorkRequest&) const = default;
};

}  // namespace figment::serve
