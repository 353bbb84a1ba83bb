// convexloc-viewer — the key queue.
#include "logic/app/key_queue.hpp"

namespace convexloc::viewer {

void KeyQueue::press(const KeyPress& k, bool typing) {
  for (const KeyBinding& b : bindings_) {
    if (b.key != k.key || (b.shift >= 0 && (b.shift == 1) != k.shift)) continue;
    if ((k.repeat && !b.repeats) || (typing && !b.always)) return;
    queued_.push_back(b.action);
    return;
  }
}

std::vector<Action> KeyQueue::drain() {
  std::vector<Action> taken;
  taken.swap(queued_);
  return taken;
}

}  // namespace convexloc::viewer
