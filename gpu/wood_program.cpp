#include "gpu/wood_program.hpp"

#include <QFile>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QVector3D>
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "params/parameter_schema.hpp"

namespace kerf {
namespace {

QVector3D toQt(glm::vec3 v) {
  return {v.x, v.y, v.z};
}

}  // namespace

QString WoodProgram::shaderFile(const QString& name) {
  QFile file(":/shaders/" + name);
  if (!file.open(QIODevice::ReadOnly))
    throw std::runtime_error("missing shader resource " + name.toStdString());
  return QString::fromUtf8(file.readAll());
}

QString WoodProgram::parameterDeclarations() {
  return shaderFile("kernels/glsl_prelude.glsl") + QString::fromStdString(glslUniformDeclarations());
}

QString WoodProgram::fragmentSource(const QString& fragmentFile, WoodSource source) {
  QString text = "#version 330 core\n";
  if (source == WoodSource::Board) text += "#define KERF_BOARD_WOOD 1\n";
  // The model's single-source kernels (core/model/kernels) around the GPU back-end (wood_model.glsl).
  text += parameterDeclarations() + QString("const int kMaxBlockKnots = %1;\n").arg(kMaxBlockKnotsOnGpu) +
          shaderFile("kernels/noise.glsl") + shaderFile("kernels/knot_checks.glsl") +
          shaderFile("knot_death.glsl") + shaderFile("wood_model.glsl") + shaderFile("kernels/wood.glsl");
  if (source == WoodSource::Board) text += shaderFile("knots.glsl") + shaderFile("board_wood.glsl");
  return text + "\n#line 1 1\n" + shaderFile(fragmentFile);
}

WoodProgram::WoodProgram(const QString& vertexFile, const QString& fragmentFile, WoodSource source) {
  const QString vertex = "#version 330 core\n" + shaderFile(vertexFile);
  if (!program_.addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
      !program_.addShaderFromSourceCode(QOpenGLShader::Fragment, fragmentSource(fragmentFile, source)) ||
      !program_.link()) {
    throw std::runtime_error("wood shader failed to build: " + program_.log().toStdString());
  }
}

WoodProgram::~WoodProgram() = default;

void WoodProgram::setParameter(QOpenGLShaderProgram& program, const ParamSpec& spec,
                               std::span<const float> value) {
  if (spec.gpu != GpuUse::Uniform) return;  // not declared in GLSL
  const QByteArray name = QByteArray::fromStdString(glslUniformName(spec));
  if (value.size() == 3)
    program.setUniformValue(name.constData(), QVector3D(value[0], value[1], value[2]));
  else
    program.setUniformValue(name.constData(), value[0]);
}

void WoodProgram::setParameters(QOpenGLShaderProgram& program, const WoodParameters& params) {
  const auto schema = parameterSchema();
  for (std::size_t i = 0; i < schema.size(); ++i) setParameter(program, schema[i], params.components(i));
}

void WoodProgram::setModel(const WoodModel& model) {
  setParameters(program_, model.params());
  const GrowthField& field = model.field();
  const PithAxis& axis = field.axis();
  program_.setUniformValue("u_axisOrigin", toQt(axis.origin));
  program_.setUniformValue("u_axisDirection", toQt(axis.direction));
  program_.setUniformValue("u_axisReference", toQt(axis.reference));
  program_.setUniformValue("u_axisBinormal", toQt(axis.binormal));

  // Knots in the block (shaders/wood_model.glsl, kMaxBlockKnots).
  const std::vector<BlockKnot>& knots = model.knots().knots();
  const int knotCount = std::min(static_cast<int>(knots.size()), kMaxBlockKnotsOnGpu);
  program_.setUniformValue("u_blockKnotCount", knotCount);
  for (int i = 0; i < knotCount; ++i) {
    const QByteArray index = "[" + QByteArray::number(i) + "]";
    program_.setUniformValue(("u_blockKnotOrigin" + index).constData(), toQt(knots[i].origin));
    program_.setUniformValue(("u_blockKnotDirection" + index).constData(), toQt(knots[i].direction));
    program_.setUniformValue(("u_blockKnotSpeed" + index).constData(), knots[i].speed);
    program_.setUniformValue(("u_blockKnotTaper" + index).constData(), knots[i].taper);
    program_.setUniformValue(("u_blockKnotTaperAge" + index).constData(), knots[i].taperAge);
    // Alive (infinity) as the largest float: a uniform's infinity is not portable GLSL 3.30.
    program_.setUniformValue(("u_blockKnotDeath" + index).constData(),
                             std::min(knots[i].deathTime, std::numeric_limits<float>::max()));
    program_.setUniformValue(("u_blockKnotUp" + index).constData(), toQt(model.knots().up(i)));
    program_.setUniformValue(("u_blockKnotSide" + index).constData(), toQt(model.knots().side(i)));
    program_.setUniformValue(("u_blockKnotId" + index).constData(), knots[i].id);
  }

  const GrowthRates& rates = field.rates();
  QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
  gl->glUniform3i(program_.uniformLocation("u_gridSize"), rates.heights, rates.azimuths, rates.radii);
  // glUniform1ui directly: QOpenGLShaderProgram's GLuint overload goes through glUniform1i.
  gl->glUniform1ui(program_.uniformLocation("u_hashSeed"), model.material().hashSeed());
  program_.setUniformValue("u_gridRange", rates.heightMin, rates.heightMax, rates.radiusMin, rates.radiusMax);
  program_.setUniformValue("u_azimuthRange", rates.azimuthMin, rates.azimuthMax);

  growthTable_ = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target3D);
  growthTable_->setFormat(QOpenGLTexture::R32F);
  growthTable_->setSize(rates.radii + 1, rates.azimuths, rates.heights);
  growthTable_->setMipLevels(1);
  growthTable_->allocateStorage(QOpenGLTexture::Red, QOpenGLTexture::Float32);
  growthTable_->setMinMagFilters(QOpenGLTexture::Nearest, QOpenGLTexture::Nearest);
  growthTable_->setData(QOpenGLTexture::Red, QOpenGLTexture::Float32, field.cumulative().data());
  growthTable_->bind(0);
  program_.setUniformValue("u_growthTable", 0);
}

}  // namespace kerf
