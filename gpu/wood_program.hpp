#pragma once
// The GLSL wood model (shaders/wood_model.glsl) as an OpenGL program: assembles the shader source
// with the schema's uniform declarations, and uploads a WoodModel (parameters, pith axis, growth table).
// Needs a current OpenGL 3.3 core context.
#include <QOpenGLShaderProgram>
#include <QOpenGLTexture>
#include <QString>
#include <memory>
#include <span>

#include "render/wood_model.hpp"

namespace kerf {

// The most block knots the shader evaluates (kMaxBlockKnots in shaders/wood_model.glsl); more are
// ignored on the GPU.
inline constexpr int kMaxBlockKnotsOnGpu = 8;

// Which wood the fragment stage evaluates: the block's procedural model (evaluateWood), or a board cut
// from a log with knots (boardWood of shaders/board_wood.glsl, set up by BoardWoodTextures).
enum class WoodSource { Block, Board };

class WoodProgram {
 public:
  // Compiles `vertexFile` and `fragmentFile` (names in the :/shaders resource) with the wood model
  // linked into the fragment stage. Throws std::runtime_error with the compiler log on failure.
  WoodProgram(const QString& vertexFile, const QString& fragmentFile, WoodSource source = WoodSource::Block);
  ~WoodProgram();

  QOpenGLShaderProgram& program() { return program_; }

  // Uploads every schema parameter, the pith frame, the growth table (texture unit 0) and the seed.
  // Call with the program bound.
  void setModel(const WoodModel& model);

  // The full fragment-stage source, as compiled (for tests and error messages).
  static QString fragmentSource(const QString& fragmentFile, WoodSource source = WoodSource::Block);
  static QString shaderFile(const QString& name);
  // kernels/glsl_prelude.glsl and the schema's `uniform WoodParameters P`: what any program that reads
  // parameters puts after its #version line.
  static QString parameterDeclarations();
  // Uploads every GpuUse::Uniform schema parameter to P.* of a bound program (members the program does
  // not use are skipped by OpenGL).
  static void setParameters(QOpenGLShaderProgram& program, const WoodParameters& params);
  // Uploads one parameter's value (1 or 3 floats) to its uniform P.name; nothing for a CpuOnly one.
  static void setParameter(QOpenGLShaderProgram& program, const ParamSpec& spec,
                           std::span<const float> value);

 private:
  QOpenGLShaderProgram program_;
  std::unique_ptr<QOpenGLTexture> growthTable_;
};

}  // namespace kerf
