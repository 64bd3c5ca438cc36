// A stand-in for openFrameworks 0.12's ofMain.h: the declarations the exported apps use,
// with oF's own signatures (libs/openFrameworks: ofLight.h, ofMaterial.h, ofShader.h, ofCamera.h,
// ofNode.h, ofGraphics.h, of3dGraphics.h, ofAppRunner.h, ofColor.h) and the GL 2.1 calls
// and constants, so that tests/openframeworks.rs can compile an export as C++17 without
// openFrameworks. Declarations only: nothing is linked.
#pragma once

#include <string>

typedef float GLfloat;
typedef int GLint;
typedef unsigned int GLenum;
enum : GLenum {
    GL_LIGHT0 = 0x4000, GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7,
    GL_AMBIENT = 0x1200, GL_DIFFUSE = 0x1201, GL_SPECULAR = 0x1202, GL_POSITION = 0x1203,
    GL_SPOT_DIRECTION = 0x1204, GL_SPOT_EXPONENT = 0x1205, GL_SPOT_CUTOFF = 0x1206,
    GL_CONSTANT_ATTENUATION = 0x1207, GL_LINEAR_ATTENUATION = 0x1208, GL_QUADRATIC_ATTENUATION = 0x1209,
    GL_EMISSION = 0x1600, GL_SHININESS = 0x1601, GL_FRONT = 0x0404, GL_BACK = 0x0405, GL_FRONT_AND_BACK = 0x0408,
    GL_LIGHT_MODEL_LOCAL_VIEWER = 0x0B51, GL_LIGHT_MODEL_TWO_SIDE = 0x0B52, GL_LIGHT_MODEL_AMBIENT = 0x0B53,
    GL_LIGHT_MODEL_COLOR_CONTROL = 0x81F8, GL_SEPARATE_SPECULAR_COLOR = 0x81FA,
    GL_NORMALIZE = 0x0BA1, GL_RESCALE_NORMAL = 0x803A, GL_MODELVIEW = 0x1700, GL_TRUE = 1, GL_FALSE = 0,
    GL_FRAGMENT_SHADER = 0x8B30, GL_VERTEX_SHADER = 0x8B31,
    GL_COLOR_MATERIAL = 0x0B57, GL_COLOR_MATERIAL_FACE = 0x0B55, GL_COLOR_MATERIAL_PARAMETER = 0x0B56,
    GL_AMBIENT_AND_DIFFUSE = 0x1602,
    GL_SHADE_MODEL = 0x0B54, GL_FLAT = 0x1D00, GL_SMOOTH = 0x1D01, GL_VERTEX_PROGRAM_TWO_SIDE = 0x8643,
};
void glLightfv(GLenum light, GLenum pname, const GLfloat* params);
void glLightf(GLenum light, GLenum pname, GLfloat param);
void glLightModeli(GLenum pname, GLint param);
void glMaterialfv(GLenum face, GLenum pname, const GLfloat* params);
void glMaterialf(GLenum face, GLenum pname, GLfloat param);
void glEnable(GLenum cap);
unsigned char glIsEnabled(GLenum cap);
void glGetIntegerv(GLenum pname, GLint* data);
void glDisable(GLenum cap);
void glMatrixMode(GLenum mode);
void glPushMatrix();
void glPopMatrix();
void glLoadIdentity();

namespace glm {
struct vec3 {
    float x, y, z;
    vec3(float x, float y, float z);
};
struct quat {
    float w, x, y, z;
    quat(float w, float x, float y, float z);
};
struct mat4 {
    mat4(float, float, float, float, float, float, float, float, float, float, float, float, float, float, float,
         float);
};
}  // namespace glm

template <typename PixelType> class ofColor_ {
public:
    ofColor_(PixelType r, PixelType g, PixelType b, PixelType a);
};
typedef ofColor_<float> ofFloatColor;

class ofNode {
public:
    virtual ~ofNode();
    void setPosition(float px, float py, float pz);
    void setGlobalPosition(const glm::vec3& p);
    void setGlobalOrientation(const glm::quat& q);
    void lookAt(const glm::vec3& lookAtPosition, glm::vec3 upVector);
};

class ofCamera : public ofNode {
public:
    void setFov(float f);
    void setNearClip(float f);
    void setFarClip(float f);
    void setAspectRatio(float aspectRatio);
    virtual void begin();
    virtual void end();
};

class ofLight : public ofNode {
public:
    void enable();
    void disable();
    void setDirectional();
    void setSpotlight(float spotCutOff = 45.f, float exponent = 0.f);
    void setPointLight();
    void setAttenuation(float constant = 1.f, float linear = 0.f, float quadratic = 0.f);
    void setAmbientColor(const ofFloatColor& c);
    void setDiffuseColor(const ofFloatColor& c);
    void setSpecularColor(const ofFloatColor& c);
};

class ofMaterial {
public:
    void setDiffuseColor(ofFloatColor oDiffuse);
    void setAmbientColor(ofFloatColor oAmbient);
    void setSpecularColor(ofFloatColor oSpecular);
    void setEmissiveColor(ofFloatColor oEmmisive);
    void setShininess(float nShininess);
    void begin() const;
    void end() const;
};

class ofShader {
public:
    bool setupShaderFromSource(GLenum type, std::string source, std::string sourceDirectoryPath = "");
    bool linkProgram();
    void begin() const;
    void end() const;
    void setUniform1i(const std::string& name, int v1) const;
    void setUniform1iv(const std::string& name, const int* v, int count = 1) const;
    void setUniform1f(const std::string& name, float v1) const;
    void setUniform3f(const std::string& name, float v1, float v2, float v3) const;
    void setUniform4f(const std::string& name, float v1, float v2, float v3, float v4) const;
};

class ofBaseApp {
public:
    virtual ~ofBaseApp();
    virtual void setup();
    virtual void draw();
};

enum ofWindowMode { OF_WINDOW = 0, OF_FULLSCREEN = 1, OF_GAME_MODE = 2 };
void ofSetupOpenGL(int w, int h, ofWindowMode screenMode);
int ofRunApp(ofBaseApp* OFSA);
void ofBackground(float r, float g, float b, float a = 255);
void ofEnableDepthTest();
void ofEnableLighting();
void ofDisableLighting();
void ofSetGlobalAmbientColor(const ofFloatColor& c);
void ofPushMatrix();
void ofPopMatrix();
void ofMultMatrix(const glm::mat4& m);
void ofRotateXDeg(float degrees);
void ofSetSphereResolution(int res);
void ofDrawSphere(float radius);
void ofSetCylinderResolution(int radiusSegments, int heightSegments, int capSegments = 2);
void ofDrawCylinder(float radius, float height);
