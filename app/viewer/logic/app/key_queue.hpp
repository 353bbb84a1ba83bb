// convexloc-viewer — the keys pressed, queued in order, each turned into one action: the
// window's key callback pushes every press (a clicker's press and release both falling
// between two frames included), the frame drains the queue whole and carries the actions
// out in order, so no press is lost or merged with another. GL-free: the key codes are the
// window's own numbers, bound to actions by the platform layer's table.
#pragma once

#include <span>
#include <vector>

#include "logic/app/actions.hpp"

namespace convexloc::viewer {

// one key bound to one action
struct KeyBinding {
  int key = 0;
  Action action;
  bool repeats = false;  // a held key's repeats act too (the step arrows)
  bool always = false;   // acts while a text field has the keyboard too (F12)
  int shift = -1;        // -1: with or without Shift; 0: without; 1: with
};

// a key going down (or repeating, held) as the window reports it
struct KeyPress {
  int key = 0;
  bool repeat = false;
  bool shift = false;
};

// the actions the keys asked for since the last drain, oldest first
class KeyQueue {
 public:
  explicit KeyQueue(std::span<const KeyBinding> bindings) : bindings_(bindings) {}
  // A press: its binding's action queued (none for an unbound key, a repeat of a key that
  // does not repeat, or while `typing` (a text field has the keyboard) unless it acts always).
  void press(const KeyPress& k, bool typing);
  // every action queued, oldest first; the queue is empty after
  std::vector<Action> drain();
  bool empty() const { return queued_.empty(); }

 private:
  std::span<const KeyBinding> bindings_;
  std::vector<Action> queued_;
};

}  // namespace convexloc::viewer
