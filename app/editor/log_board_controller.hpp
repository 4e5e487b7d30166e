#pragma once
// Logs and the board cut from them (docs/editor.md, "Logs and boards"): a .kerflog file or Gran_1 folder
// (read in the background), or a random log, attached to the document as one undo step (a new document when
// none is open) with the default flat-sawn board; the log view, the board's placement and the knot table
// follow the document; the board's wood for the 3D view and the cut is made in the background (latest
// wins). CLT, veneer and plywood panels from the log are rendered into the Panel view (log_board_panel.cpp).
#include <QString>
#include <cstdint>
#include <memory>

#include "editor_controller.hpp"

class QAction;

namespace kerf {

class BoardControls;
class CutView;
class FacesController;
class ImagePane;
class KnotTable;
class LogView;
class PanelControls;
class Viewport3D;
struct BoardWood;
struct KnotShape;
struct LogModel;
struct PanelOptions;

class LogBoardController : public EditorController {
  Q_OBJECT

 public:
  // The views it drives (made with the window's docks).
  struct Views {
    LogView* logView;
    BoardControls* boardControls;
    KnotTable* knotTable;
    PanelControls* panelControls;
    ImagePane* panelPane;
    Viewport3D* viewport;
    CutView* cutView;
  };
  // The actions whose state follows the log (made with the window's menus).
  struct Actions {
    QAction* saveLog;
    QAction* closeLog;
    QAction* showPhotosOn3d;
  };
  LogBoardController(const EditorContext& context, FacesController* faces, const Views& views);
  void setActions(const Actions& actions);

  void chooseLog();  // a file dialog, then openLog
  void openLog(const QString& path);
  void chooseRandomLog();  // asks for the seed
  void openRandomLog(std::uint32_t seed);
  // Writes the log alone (asks for the file when `path` is empty).
  bool saveLogAs(QString path = {});
  void closeLog();
  // CLT, veneer or plywood from the open log, rendered in the background into the Panel view.
  void showPanel(const PanelOptions& options);

 signals:
  // A log is attached (its faces follow with facesPreviewed / facesRendered).
  void logOpened();
  // A panel (showPanel) is shown at full resolution.
  void panelRendered();

 private:
  void attachLog(LogModel log);
  void showLog();
  void showDock(const char* name);
  // The board's wood for the 3D view and the cut panel (GLSL, per fragment); `logOrParameters`: the
  // knot field and the colour map are rebuilt, otherwise only the board moved.
  void updateBoardWood(bool logOrParameters);
  void addKnot();
  void deleteKnot(int knot);
  void editKnot(int knot, const KnotShape& shape);

  FacesController* faces_;
  Views views_;
  Actions actions_{};
  bool logShown_ = false;                       // the views show a log (its board's faces)
  std::shared_ptr<const BoardWood> boardWood_;  // what the 3D view and the cut panel show in log mode
  int boardWoodJob_ = 0;                        // the knot field being made in the background
  int panelJob_ = 0;
};

}  // namespace kerf
