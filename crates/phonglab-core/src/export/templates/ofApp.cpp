// {{source_comment:comment}}
#include "ofApp.h"

void ofApp::setup() {
{{camera}}{{lights}}    // {{material_comment:comment}}
{{material}}{{shader}}}

void ofApp::draw() {
{{draw}}}
