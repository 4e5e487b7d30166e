#pragma once
// The document's files: opening a .kerf project, a sample folder or the demo (in the background; the
// current document stays open until the new one has loaded, and stays if loading fails), saving, the
// recent files, recovering what an earlier session's autosave kept, a photo dropped on a face, and
// File ▸ Import Photos (files_import.cpp).
#include <QString>
#include <QStringList>
#include <functional>

#include "document_jobs.hpp"
#include "editor_controller.hpp"

class QMenu;

namespace kerf {

class Autosave;
class FacesController;
class RecentFiles;

class FilesController : public EditorController {
  Q_OBJECT

 public:
  FilesController(const EditorContext& context, FacesController* faces);

  // The recent files, listed in `menu` (File ▸ Open Recent).
  void setRecentMenu(QMenu* menu);
  RecentFiles* recentFiles() const { return recent_; }
  Autosave* autosave() const { return autosave_; }

  void chooseDocument();  // asks to save the current one, then for the file
  void openDocument(const QString& path);
  // Opens `path` in place of the current document once that is saved or discarded (asks).
  void openInstead(const QString& path);
  // Generates the demo into `folder` if it is not there yet, then opens it.
  void openDemo(const QString& folder, const DemoOptions& options = demoOptions());
  static DemoOptions demoOptions();  // what the editor's demo uses: 256 px faces

  // Saves to the document's file (or asks for one); returns false if nothing was saved.
  bool save();
  bool saveAs(QString path = {});
  // Asks whether to save a modified document; false: the user cancelled.
  bool maybeSave();
  // While false (tests), closing a modified document discards it without asking.
  void setAskBeforeDiscarding(bool ask) { askBeforeDiscarding_ = ask; }
  // Offers to recover the copies an earlier session's autosave left behind (asks the user).
  void offerRecovery();
  // Opens an autosave copy as a modified document attached to its original file.
  void recover(const QString& autosaveFile);

  void dropPhoto(FaceId face, const QString& path);
  // The dialog on `files` (a file chooser first when empty), then the faces written in the background and
  // applied as one undo step (photosImported()).
  void importPhotos(const QStringList& files = {});

 signals:
  // A document was opened from `path` (a .kerf file or a folder of photos) and is now the document.
  void documentOpened(const QString& path);
  // Loading failed; the message is also shown in a (non-blocking) message box and the log.
  void documentFailed(const QString& message);
  // The opened sample's species, as a preset id (empty when the folder's name names none).
  void speciesOpened(const QString& presetId);
  void photosImported();

 private:
  void connectImport();  // files_import.cpp
  void startLoad(const QString& what, std::function<LoadedDocument(const Progress&)> load);
  void documentLoaded(const LoadedDocument& loaded);

  FacesController* faces_;
  RecentFiles* recent_ = nullptr;
  Autosave* autosave_;
  bool askBeforeDiscarding_ = true;
  int importJob_ = 0;
};

}  // namespace kerf
