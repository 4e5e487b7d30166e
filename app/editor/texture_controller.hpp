#pragma once
// The Texture work: Infer Texture from Photos runs the texture inference of `kerf-cli texture` on the
// document's photos and fitted field (a job with live preview, cancellable) and applies the result as one
// undo step. The options are the core's defaults unless set (tests: smaller).
#include <memory>

#include "editor_controller.hpp"
#include "texture/texture_inference.hpp"
#include "texture_job.hpp"

namespace kerf {

class FacesController;
class RingsController;

class TextureController : public EditorController {
  Q_OBJECT

 public:
  TextureController(const EditorContext& context, FacesController* faces, const RingsController* rings);

  void inferTexture();
  void setTextureOptions(const TextureInferenceOptions& options) { textureOptions_ = options; }
  const TextureInferenceOptions& textureOptions() const { return textureOptions_; }
  bool isRunning() const;

  // A texture that has landed (from Infer Texture or from Reconstruct), applied as one undo step; false
  // (with a message) when it is not valid.
  bool applyTexture(std::shared_ptr<const TextureJobResult> texture);
  // The texture being inferred, on every view before it is applied.
  void showTexturePreview(const WoodParameters& params);

 signals:
  // Infer Texture finished and its result is applied / an improved texture is previewed on the faces /
  // it failed or was cancelled (the message is also in the log and, for errors, a message box).
  void textureInferred();
  void texturePreviewed();
  void textureJobFailed(const QString& message);

 private:
  void fail(const QString& message);
  void ended(int id, const QString& message);

  FacesController* faces_;
  const RingsController* rings_;
  int textureJob_ = 0;
  TextureInferenceOptions textureOptions_;
};

}  // namespace kerf
