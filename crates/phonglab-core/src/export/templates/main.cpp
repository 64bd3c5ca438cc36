// {{renderer_comment:comment}}
#include "ofMain.h"
#include "ofApp.h"

int main() {
    ofSetupOpenGL(512, 512, OF_WINDOW);
    ofRunApp(new ofApp());
}
