// {{title:comment}}
#pragma once

#include "ofMain.h"

class ofApp : public ofBaseApp {
public:
    void setup() override;
    void draw() override;

private:
    ofCamera cam;
    ofMaterial material;
{{members}}};
