// convexloc-viewer — the frame's windows: the panels on the left (Shape, Method, Points or
// Slicing plane, View), the legend and the inspector on the right (floating over the scene
// in narrow windows), the error and notice toasts, the labels written over the scene; and
// what the viewer does for each key action.
#pragma once

#include <glm/glm.hpp>

#include "gl/renderer.hpp"
#include "gl/scene_view.hpp"
#include "logic/app/actions.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the panel widths in window pixels, at the current font scale
float leftPanelWidth(const Model& model, glm::dvec2 window);
float rightPanelWidth(const Model& model, glm::dvec2 window);
// the part of the window the scene has to itself (right of the panel when it shows)
ScreenRect sceneArea(const Model& model, glm::dvec2 window);

// fits the camera to the shape in the scene area, leaving room for the caption and the
// floating legend; for `now` + 1.5 s a change of the legend's size fits again
void fitScene(Model& model, UiState& ui, glm::dvec2 window, double now);

// finds the shape files in ui.assetDir
void scanAssets(UiState& ui);

// carries out a key's action on the scene shown (or asks the frame loop, for a screenshot)
void perform(const Action& action, Model& model, UiState& ui);

// every window of the frame; `now` in seconds
void drawUi(Model& model, Renderer& renderer, UiState& ui, double now);

// the draw lists' labels, written on ImGui's background draw list over the scene, kept off
// the windows floating over it where they can
void drawLabels(Model& model, const UiState& ui, const SceneView& view);

}  // namespace convexloc::viewer
