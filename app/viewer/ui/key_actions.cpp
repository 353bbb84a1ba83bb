// convexloc-viewer — the keys' actions.
#include "ui/key_actions.hpp"

#include <algorithm>
#include <iterator>

#include "ui/panels/lecture_panel.hpp"

namespace convexloc::viewer {

void perform(const Action& action, Model& model, UiState& ui) {
  // the panel's settings, taken from the scene first where the scene's changed
  followSpray(
      ui, model.dim == Dim::Two ? model.scene2d.spraySettings() : model.scene3d().spraySettings());
  const SpraySettings spray{static_cast<std::size_t>(ui.sprayCount), ui.spraySeed + 1,
                            ui.sprayNear};
  switch (action.kind) {
    case ActionKind::Screenshot: ui.screenshotRequested = true; break;
    case ActionKind::Fit: model.requestFit(); break;
    case ActionKind::ToggleLines:
      if (model.dim == Dim::Two) model.setLinesMode(!model.lines2d.enabled());
      // 3D: the Planes mode
      if (model.dim == Dim::Three) model.setPlanesMode(!model.planes3d.enabled());
      break;
    case ActionKind::ToggleUi:
      model.settings.showUi = !model.settings.showUi;
      model.requestFit();  // the scene's area changed
      break;
    case ActionKind::ToggleTheme:
      model.settings.theme = model.settings.theme == Theme::Dark ? Theme::Light : Theme::Dark;
      break;
    case ActionKind::ClearPoint:
      if (model.dim == Dim::Two) {
        model.scene2d.clearProbe();
        model.lines2d.clearLine();
      } else {
        model.scene3d().clearProbe();
        model.scene3d().pin(-1);
      }
      break;
    case ActionKind::NewSpray:
      ++ui.spraySeed;
      if (model.dim == Dim::Two)
        model.scene2d.spray(spray);
      else
        model.scene3d().spray(spray);
      break;
    // the placed point's query step by step
    case ActionKind::PrevStep: model.stepBy(false); break;
    case ActionKind::NextStep: model.stepBy(true); break;
    case ActionKind::ToggleRadii: model.setPaperMode(!model.settings.paperMode); break;
    case ActionKind::SaveSvg: ui.svgRequested = true; break;
    case ActionKind::TogglePresent:
      model.settings.present = !model.settings.present;
      model.settings.showUi = !model.settings.present;
      model.requestFit();
      break;
    case ActionKind::ToggleLegend:
      model.settings.showLegend = !model.settings.showLegend;
      model.requestFit();
      break;
    case ActionKind::TextLarger:
    case ActionKind::TextSmaller: {
      // an eighth per step, between half and three times the slide's own size
      const float f = action.kind == ActionKind::TextLarger ? 1.125f : 1.0f / 1.125f;
      model.settings.textZoom = std::clamp(model.settings.textZoom * f, 0.5f, 3.0f);
      model.requestFit();
      break;
    }
    case ActionKind::ChooseMethod:
      if (model.dim == Dim::Two)
        model.scene2d.setMethod(kAllMethods2D[action.method]);
      else if (action.method < static_cast<int>(std::size(kAllMethods3D)))
        model.scene3d().setMethod(kAllMethods3D[action.method]);
      break;
    // a lecture's slides
    case ActionKind::NextSlide:
    case ActionKind::PreviousSlide:
    case ActionKind::FirstSlide:
    case ActionKind::LastSlide: moveSlide(action.kind, model, ui); break;
    case ActionKind::ToggleBlank: ui.show.blank = !ui.show.blank; break;
    case ActionKind::ToggleNotes: ui.showNotes = !ui.showNotes; break;
    case ActionKind::DismissProblems: ui.show.dismiss(); break;
  }
}

}  // namespace convexloc::viewer
