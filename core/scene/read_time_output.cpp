// Top-level keys `time` and `output`.
#include <fmt/format.h>

#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"
#include "core/scene/time_limits.h"

namespace fissure {

namespace {

void read_time(ConfigMap& top, TimeControls& time) {
  std::optional<ConfigNode> node = top.required("time", "a time section with at least `end`");
  if (!node) return;
  ConfigMap map(*node, scene_keys::time);
  std::optional<double> end;
  if (auto e = map.required("end", expectation(quantity::time, Range::positive())))
    if ((end = e->quantity(quantity::time, Range::positive()))) {
      time.end_time = *end;
      time.unit = time_unit_of(e->text(), *end);
    }
  map.read("max_steps", time.max_steps, 1);
  if (end) time.min_step = default_min_step(*end);
  if (auto m = map.optional("min_step")) {
    if (auto min_step = m->quantity(quantity::time, Range::positive())) {
      if (end && *min_step >= *end)
        m->error(fmt::format("found {}; expected a time shorter than time.end ({} s)", m->found(),
                             *end));
      else if (!end || check_resolvable(*m, *min_step, *end))
        time.min_step = *min_step;
    }
  }
}

void read_output(ConfigMap& top, OutputControls& output, const TimeControls& time) {
  std::optional<ConfigNode> node = top.optional("output");
  if (!node) return;
  ConfigMap map(*node, scene_keys::output);
  if (auto i = map.optional("interval")) {
    if (auto interval = i->quantity(quantity::time, Range::non_negative())) {
      if (*interval > 0 && time.end_time > 0 && time.end_time / *interval > kMostFrames)
        i->error(
            fmt::format("found {}; expected an interval of at least time.end / {:g} = {:g} s "
                        "(at most {:g} output frames), or 0 (every_steps)",
                        i->found(), kMostFrames, time.end_time / kMostFrames, kMostFrames));
      else
        output.interval = *interval;
    }
  }
  map.read("every_steps", output.every_steps, 0);
  map.read("hdf5", output.hdf5);
  map.read("checkpoint_steps", output.checkpoint_steps, 0);
  if (auto w = map.optional("checkpoint_wall_time"))
    if (auto wall = w->quantity(quantity::time, Range::non_negative()))
      output.checkpoint_wall_time = *wall;
}

}  // namespace

void read_time_output(ConfigMap& top, SceneDraft& draft) {
  read_time(top, draft.scene.time);
  read_output(top, draft.scene.output, draft.scene.time);
}

}  // namespace fissure
