# phonglab's messages in English.

## app

present = Present (F5)
space-object = Object
space-world = World
space-eye = Eye
wrong-cause-normals-by-m = Normals transformed by M instead of its inverse transpose
wrong-why-normals-by-m = Under a scale that differs along the axes, M moves the surface one way and its normals another: M n is no longer perpendicular to the surface, and (M^-1)^T n is.
wrong-cause-normal-not-normalised = The normal not normalised (GL_NORMALIZE off under a scaled modelview)
wrong-why-normal-not-normalised = A modelview that scales by { $scale } makes the transformed normal 2 long, and nothing brings it back to 1: n · L doubles, and with it the diffuse term; near the highlight n · H passes 1, and the power s_rm blows the specular term up into a white patch.
wrong-cause-reflection-for-halfway = The reflection vector (R · V) used where the halfway vector (n · H) belongs
wrong-why-reflection-for-halfway = The angle between R and V is about twice the angle between n and H, so R · V falls off faster: at the same exponent the highlight is smaller.
wrong-cause-gouraud-misses-highlight = Gouraud shading: lit only at the vertices, so a highlight between them is lost
wrong-why-gouraud-misses-highlight = The highlight falls between the coarse sphere’s vertices: none of them sees it, and interpolating their colours cannot make it.
wrong-cause-specular-facing-away = Specular light on faces turned away from the light (no f_i)
wrong-why-specular-facing-away = OpenGL multiplies the specular term by f_i, 1 only where n · L > 0. Without it n · H can still be positive on the dark side: a highlight glows where no light reaches.
wrong-cause-attenuation-object-space = Attenuation computed with the distance in object space
wrong-why-attenuation-object-space = The model scales by { $scale }, so distances in object space are 4 times those in eye space: at = k0 + k1 d + k2 d² grows, every term is divided by more, and the light fades too soon. OpenGL measures d in eye space.
wrong-cause-light-before-view = The light’s position given before the view transform
wrong-why-light-before-view = glLightfv(GL_POSITION) multiplies the position by the modelview current at that moment. Given before gluLookAt, it is taken in eye coordinates: the light rides with the camera instead of staying in the world.
wrong-probe-line = bytes { $rgba }, n · L = { $ndotl }, { $cosine } = { $ndoth }, 1/at = { $att }, diffuse { $diffuse }, specular { $specular }
wrong-key-cause = Cause: { $cause }.
wrong-key-formulas = Right: { $right }. The mistake: { $wrong }.
wrong-formula-gouraud-right = lighting per fragment (Phong)
wrong-formula-gouraud-wrong = lighting per vertex, its colours interpolated (Gouraud)
wrong-formula-facing-away-right = f_i = 1 only where n · L > 0
wrong-formula-facing-away-wrong = f_i = 1 everywhere
wrong-formula-attenuation-right = d = |P_pli - P| in eye space
wrong-formula-attenuation-wrong = d measured in object space
wrong-formula-light-right = gluLookAt(...), then glLightfv(GL_POSITION, p)
wrong-formula-light-wrong = glLightfv(GL_POSITION, p), then gluLookAt(...)
wrong-key-pixel = The probe at pixel ({ $x }, { $y }), where the two pictures differ most ({ $count } pixels differ):
wrong-key-right = drawn right: { $line }
wrong-key-wrong = with the mistake: { $line }
wrong-key-term = The term that changes most at this pixel: { $term } ({ $name }), its luminance from { $right } drawn right to { $wrong } with the mistake.
wrong-key-normals = The fragment’s normal turns by { $degrees }°.
share-too-long = the link is { $length } characters long; phonglab reads at most { $most }
share-version = the link is of version “{ $found }”; this phonglab reads v{ $version }
share-damaged = the link is damaged: it was cut or changed on the way. Copy the whole link again, from its start to its last character
share-choice = the link asks for something this phonglab does not know: “{ $line }”
scene-link-refused = { $link }: { $why }
scene-link-empty = the link holds no scene (a shared scene's link ends in #v1. and the scene's data): copy the whole link
share-too-big = it inflates past { $most } bytes, more than phonglab reads (more than any scene phonglab writes)
share-make-too-long = the link would be { $length } characters long, and phonglab opens links of at most { $most }: shorten the scene's name
share-mesh-folders = the link names the mesh “{ $path }” with its folders; a link carries a mesh's file name alone, and phonglab never reads a path a link names: only the file name { $name } is kept (open that file to show it), and the sphere is shown until then
mesh-missing-kept = The mesh { $path } is missing or cannot be read ({ $error }); the scene is kept and shown on the sphere. Open the mesh again to show it.
shader = Shader

## names

doc-worksheet = the worksheet, mview{ $k }
doc-worksheet-preset = Worksheet, mview{ $k }

## presets

doc-phong-demo = the Phong demo
doc-spotlight = a spotlight
doc-three-lights = three coloured lights and a headlight
doc-of-set-color = openFrameworks' ofSetColor under lighting
doc-gouraud-misses-the-highlight = why Gouraud misses the highlight
doc-redbook-teapot = Red Book teapots: { $material }

## controls

specular-blinn-phong-normalised = Normalised Blinn-Phong (n.H)·(ns+8)/8π
ruleset-worksheet = Worksheet
ruleset-demo = Phong demo
pow-exact = exact pow
lights-count =
    { $count ->
    [one] { $count } light
    *[other] { $count } lights
    }
light-tab = Light { $index }
light-ambient = Light ambient
light-diffuse = Light diffuse
light-specular = Light specular
attenuation-constant = Constant attenuation
attenuation-linear = Linear attenuation
attenuation-quadratic = Quadratic attenuation
spot-direction = Spot direction
spot-cutoff = Spot cutoff
spot-exponent = Spot exponent
material-ambient = Material ambient
material-diffuse = Material diffuse
material-specular = Material specular
material-emission = Material emission
material-shininess = Material shininess
quantity-vertex-position = Vertex position (object space)
quantity-vertex-normal = Vertex normal (object space)
quantity-light-position = Light position
quantity-material-alpha = Material alpha
quantity-modelview = Modelview matrix
quantity-light-modelview = Modelview when the light was placed
scene-ambient = Scene ambient
local-viewer = Local viewer
two-sided = Two-sided lighting
vertex = Vertex
normal = Normal
camera = Camera
camera-kind-worksheet = Worksheet modelview
camera-kind-of = openFrameworks camera
camera-kind-matrix = Typed 4x4

## result

typed-empty = no value
typed-not-a-number = "{ $text }" is not a number
typed-not-finite = { $text } is not a finite number
typed-too-large = { $text } is beyond single precision's range (±3.4e38)
typed-too-small = { $text } is too small for single precision: it would be 0

## explain

explain-heading = { $side } side, { $lights }, { $precision }, rules: { $rules }
side-front = front
side-back = back
note-line = note: { $note }
step-normal = Transformed normal
step-normal-back = Transformed normal (back side: -N)
step-position = Vertex in eye space
step-light-position = Light in eye space
step-l = Light vector
step-distance = Distance to the light
step-v = View vector
step-ambient = Ambient term
step-diffuse = Diffuse term
step-h = Halfway vector
step-r = Reflection vector
step-specular = Specular term
step-attenuation = Attenuation
step-spot = Spotlight
step-share = This light's share
step-scene-ambient = Scene ambient
step-emission = Emission
step-primary = Vertex colour
step-secondary = Secondary colour
step-clamped = Colour as drawn
note-color-material = GL_COLOR_MATERIAL ({ $mode }, { $face }): { $name } is the current colour (glColor) { $color }, not the { $set } glMaterial set
formula-normal-gl = vertexNormal = (M^-1)^T · vertexNormal   (OpenGL's N)
formula-normal-gl-normalize = vertexNormal = normalize((M^-1)^T · vertexNormal)   (OpenGL's N, GL_NORMALIZE)
formula-normal-gl-rescale = vertexNormal = f · (M^-1)^T · vertexNormal, f = 1/|row 3 of M^-1|   (OpenGL's N, GL_RESCALE_NORMAL)
formula-normal-ws = vertexNormal = mview · vertexNormal   (the worksheet: M itself; OpenGL: (M^-1)^T)
formula-normal-ws-normalize = vertexNormal = normalize(mview · vertexNormal)   (the worksheet: M itself; OpenGL: (M^-1)^T)
formula-normal-ws-rescale = vertexNormal = f · mview · vertexNormal, f = 1/|row 3 of M^-1|   (the worksheet's M)
formula-position = vertexPos = mview · vertexPos, divided by w   (OpenGL: P = M v)
formula-light-position = lightPos = mview · lightPos   (OpenGL: P_l, the modelview when the light was placed times GL_POSITION)
formula-l-positional = vlv = normalize(lightPos − vertexPos)   (OpenGL: L = normalize(P_l − P))
formula-l-directional = vlv = normalize(lightPos)   (directional, w = 0; OpenGL: L = normalize(P_l.xyz))
formula-v-local = vov = normalize(obs − vertexPos), obs = [0 0 0 1]   (local viewer; OpenGL: V = −P/|P|)
formula-v-worksheet = vov = normalize(obs − vertexPos), obs = vertexPos · [1 1 0 1]   (the worksheet's infinite viewer: (0, 0, −sign z))
formula-v-infinite = vov = [0 0 1 0]   (infinite viewer; OpenGL: V = (0, 0, 1))
formula-r-demo = R = 2 max(vertexNormal · vlv, 0) vertexNormal − vlv   (the demo's)
gate-lit-side = f = 1 if cosTheta > 0, else 0
gate-positive = f = 1 if { $cos } > 0, else 0
gate-none = no gate: f = 1 always
formula-specular = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns   ({ $gate }; f = { $f }; OpenGL: s_cl · s_cm · max(n · h, 0)^s_rm)
formula-specular-normalised = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns · (ns + 8)/(8π)   ({ $gate }; f = { $f }; energy-conserving Blinn-Phong: the narrower the highlight, the brighter, the light it reflects the same; OpenGL has no such factor)
formula-at = at = atC + atLin · d + atQuad · d²   (OpenGL: the terms are divided by k0 + k1 d + k2 d²)
formula-at-directional = at = 1   (directional)
formula-spot = spot = max(−L · s, 0)^e if −L · s >= cos(cutoff) = { $cutoff }, else 0;  −L · s = { $angle }
formula-spot-none = spot = 1   (cutoff 180: not a spotlight)
formula-share-separate = Ilight = spot · (Iamb + Idif) / at   (specular goes to the secondary colour)
formula-scene-ambient = a_cm a_cs   (light-model ambient)
formula-i-opengl = I = e_cm + a_cm a_cs + sum of the lights' shares
formula-i-worksheet = I = (Iamb + Idif + Ispec) / at, summed over the lights   (the worksheet's I)
formula-secondary = sum of spot · Ispec / at   (separate specular)
formula-clamped = rgba clamped to [0, 1]; alpha = diffuse alpha
note-demo-space = the Phong demo lights in object space with its eye at (-4, 0, -8); here eye space is object space moved by (4, 0, 8), so that eye is the origin: every vector and term is the demo's
note-vov-behind = the worksheet's text says vov is always [0 0 1 0]; its code gives [0 0 -1 0] here, as the vertex is behind the eye (z > 0)
note-no-distance = directional light: no distance
mview-note-gap = so M n, the worksheet's normal, points { $angle } away from OpenGL's (M^-1)^T n, and N and every term after it differ from OpenGL's
mview-note-small-gap = M n and OpenGL's (M^-1)^T n point { $angle } apart here
mview-note-singular = M is singular: OpenGL's (M^-1)^T n does not exist
mview-note-rotation = M is a rotation to the 6 digits it is printed with (row lengths { $lengths }); { $gap }
mview-note-rows = rows { $first } and { $second } are { $angle } apart
mview-note-rows-square = its rows are 90° apart
mview-note-not-rotation = M is not a rotation: { $rows } (a rotation's rows are 90° apart and of length 1; these have lengths { $lengths }); { $gap }

## view

object-sphere = Sphere
object-teapot = Teapot
object-cylinder = Cylinder
object-mesh = Your mesh
framing-orbit = Orbit camera
framing-clip = Clip space (the demo's)
fix-light-world = light fixed in the world
fix-true-normals = the surface's true normals
fix-highlight-colour = highlight in the light's colour
why-light-world = The demo lights untransformed positions and normals, so its light turns with the object; the document's own fix transforms them by mvMatrix (for a rotation its inverse transpose is itself), and the light stays put while the object turns.
why-true-normals = normalize(position) is the normal of a sphere about the origin only; the teapot's and the cylinder's surfaces point elsewhere, and their true normals light them as they are.
why-highlight-colour = The demo multiplies the specular term by the object's red; OpenGL multiplies the light's specular colour by the material's specular colour (white here), so a highlight shows the light's colour.

## student-code

export-target-notebook = Jupyter notebook (the worksheet's)
export-target-pyopengl = Python program (PyOpenGL + GLUT)
export-target-openframeworks = openFrameworks app (ofApp.h, ofApp.cpp, main.cpp)
export-target-glsl = GLSL shaders
notebook-refused = the notebook is not written for this scene: explain takes a limit here ({ $reason }), and the notebook's NumPy would print nan or stop instead; export it as a PyOpenGL program, or change the scene
nb-title =
    # Computing a vertex's colour with OpenGL lighting

    Scene: **{ $scene }**, written by phonglab (rules: { $rules }).

    obs: change the variables' values to match the configuration used in the openFrameworks app; each cell prints what `phonglab explain` prints, step by step.
nb-vertex =
    Initialising the vertex to compute:

    - screen size
    - pos (x, y, z, 1)
    - normal vector (x, y, z, 0)
nb-light-material =
    Initialising the light's and the material's parameters

    - position/direction (x, y, z, 0/1)
    - light l_ambient, l_diffuse, l_specular
    - light constant, linear and quadratic attenuation
    - light spot direction, spot_cutoff, spot_coefficient
    - material k_ambient, k_diffuse, k_specular, shininess_ns
nb-settings = What this scene uses beyond the worksheet (phonglab wrote the cells below for these settings; to change them, change the scene in phonglab and export again):
nb-modelview =
    Initialising the modelview matrix

    The lookat transforms the modelview matrix: to do the calculations we need to transform the vectors and positions we use with the modelview matrix.
nb-light-mview-comment = # each light's position is transformed by the modelview that was current when glLight(GL_POSITION) was called
nb-color-material-comment = # GL_COLOR_MATERIAL ({ $mode }, { $face }): the material colours it tracks are the current colour, glColor = { $color }, not what glMaterial set
nb-vectors =
    Compute the vectors needed and normalise them:

    - the vertex's normal
    - vector lightPos - vertexPos (vlv)
    - vector obsPos - vertexPos (vov)

    For a directional light the vector (lightPos - vertexPos) is not needed: we use lightPos itself.

    The vector (obsPos - vertexPos) is computed differently for `glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, true/false)`: when **true**, obs = [0 0 0 1]; when **false**, obs = vertexPos * [1 1 0 1], the vertex with its z set to 0, so vov = obs - vertexPos = [0 0 -z 0] before it is normalised: only its z component is left.

    The worksheet says of **false**: "vov vai sempre resultar em [0 0 1 0]" (vov always comes out as [0 0 1 0]). That holds only for a vertex in front of the eye (its z in eye space < 0): for a vertex behind the eye (z > 0) this formula gives [0 0 -1 0], and at z = 0 vov has no direction to normalise (0/0). (OpenGL's infinite viewer is always V = (0, 0, 1).)

    More about this at <https://registry.khronos.org/OpenGL-Refpages/gl2.1/xhtml/glLightModel.xml>
nb-normal-matrix-comment = # OpenGL transforms normals by the inverse transpose of the modelview's 3x3: (M^-1)^T n
nb-normal-as-is-comment = # the normal is used as transformed (GL_NORMALIZE is off): not divided by its length
nb-infinite-viewer-comment =
    #localViewer
    #false (OpenGL: the viewer infinitely far along +z, V = (0, 0, 1))
nb-ambient =
    Computing the ambient component:

    - I<sub>amb</sub> = Light<sub>amb</sub> × Material<sub>amb</sub>
nb-diffuse =
    Computing the diffuse component:

    - I<sub>dif</sub> = Light<sub>dif</sub> × Material<sub>dif</sub> × cos(θ)
    - θ = the angle between the normal and the vector (lightPos - vertexPos)
    - θ ∈ [0°, 90°]
nb-acos-comment = # (cosTheta limited to [-1, 1]: rounding can take the dot product of two unit vectors just past 1, where acos fails)
nb-specular-blinn =
    Computing the specular component

    Phong's model defines the specular component as I<sub>spec</sub> = Light<sub>spec</sub> × Material<sub>spec</sub> × cos(γ)<sup>ns</sup>, γ the angle between the light's reflected vector and the observer.

    But the OpenGL used in openFrameworks uses a variation of Phong's model:

    - I<sub>spec</sub> = Light<sub>spec</sub> × Material<sub>spec</sub> × cos(β)<sup>ns</sup>
    - β is the angle between the normal and the **halfway** vector of (light - pos) and (obs - pos)
    - β ∈ [0°, 90°]
    - H = (vlv + vov) / |vlv + vov|
nb-specular-phong =
    Computing the specular component, Phong's model

    - I<sub>spec</sub> = Light<sub>spec</sub> × Material<sub>spec</sub> × cos(α)<sup>ns</sup>
    - α is the angle between R, the light's vector reflected about the normal, and the observer
    - R = 2 (N · vlv) N - vlv
nb-gate-lit-side-comment = # OpenGL: no specular from a light behind the surface (f = 0 where N · L <= 0)
nb-specular-normalised =
    Normalised (energy-conserving) Blinn-Phong, as modern engines light: the term is multiplied by (ns + 8)/(8π), so a sharper highlight (a larger ns) is brighter and the light it reflects stays about the same. OpenGL's fixed-function lighting has no such factor.
nb-attenuation =
    Computing the attenuation:

    - at = at<sub>constant</sub> + d × at<sub>linear</sub> + d² × at<sub>quadratic</sub>

    only for a point light or a spotlight!
nb-spot = The spotlight: inside the cone (the angle between -vlv and the spot direction at most spotCutoff), spot = cos<sup>spotCoef</sup> of that angle; outside, 0; 1 for a light that is not a spotlight (spotCutoff 180).
nb-final =
    Final calculation:

    - I<sub>final</sub> = (I<sub>amb</sub> + I<sub>dif</sub> + I<sub>spec</sub>)/at
nb-glcolor-comment = # the colour as drawn: clamped to [0, 1]; its alpha is the diffuse colour's as OpenGL lights it (1, or matAlpha; the current colour's where GL_COLOR_MATERIAL tracks the diffuse), not matDif[3]: the colours above are written [r g b 0]
nb-back = The back side (two-sided lighting): the same terms with the normal reversed (-vertexNormal) and the back material; the names end in Back.
nb-no-spot-comment = # not a spotlight (spotCutoff 180)
import-unreadable = { $place }: cannot read `{ $line }`: { $reason }; ignored
import-changed-in-place = it changes a given in place (a part of it, or with +=, *=, ...), which phonglab does not follow: assign the whole value in one line
import-no-givens = this is not a worksheet-style notebook or script: it assigns none of vertexPos, vertexNormal, lightPos, matDif, mview
import-not-notebook = not a Jupyter notebook: { $reason }
import-no-cells = it has no cells
import-place-cell = cell { $cell }, line { $line }
import-place-line = line { $line }
import-reason-extra = unexpected `{ $token }`
import-reason-string = a string is not closed
import-reason-char = the character `{ $char }` is not understood
import-reason-expected = expected `{ $token }`, found `{ $found }`
import-reason-end = the expression ends too soon
import-reason-number = `{ $token }` is not a number
import-reason-name = `{ $name }` is not known here (only numbers, arrays and names assigned before are read)
import-reason-arithmetic = `{ $op }` between values of different shapes
import-missing = { $name } is not assigned: the worksheet's value { $value } is used
import-malformed = { $place }: { $name } should be { $want }; the worksheet's value is used
import-want-vector = 4 numbers, [x, y, z, w]
import-want-number = a number
import-want-matrix = 4 rows of 4 numbers
import-not-finite = { $place }: { $name } is { $value }, not a finite number; the worksheet's value is used
import-too-large = { $place }: `{ $line }` { $reason }: the file is not read (a worksheet's givens are a few small arrays)
import-limit-depth = nests more than { $depth } deep
import-limit-elements = holds more than { $count } numbers, strings and lists
import-limit-bytes = holds more than { $count } bytes of strings
import-limit-tokens = holds more than { $count } tokens (numbers, names, operators and brackets)
import-limit-total = brings the names assigned so far past what phonglab reads: it { $limit }
bytes-described = { $count ->
        [one] { $bytes } byte
       *[other] { $bytes } bytes
    } ({ $scaled })
bytes-counted = { $count ->
        [one] { $bytes } byte
       *[other] { $bytes } bytes
    }
obj-index-not-number = line { $line }: { $what } index { $index } is not a number
obj-index-out-of-range = line { $line }: { $what } index { $index } is out of range (there are { $count })
obj-what-vertex = vertex
obj-what-texture = texture
obj-what-normal = normal
obj-cannot-read-line = line { $line }: cannot read: { $error }
obj-line-too-long = line { $line } is longer than { $bytes } bytes: not an OBJ file
obj-too-many-triangles = line { $line }: more than { $max } triangles, the most phonglab shades
obj-not-a-number = line { $line }: { $word } is not a number
obj-vertex-needs = line { $line }: a vertex needs 3 finite numbers
obj-normal-needs = line { $line }: a normal needs 3 finite numbers
obj-face-needs = line { $line }: a face needs at least 3 corners
obj-no-faces = no faces
obj-note-fanned = faces of more than 3 corners (the first on line { $line }) were fanned into triangles
obj-note-normals = faces without normals (the first on line { $line }): their vertices' normals were computed as the area-weighted mean of their faces' normals
obj-note-fitted = centred and scaled by { $scale } to fit the view (radius 0.5)
obj-beyond-single = coordinates beyond single precision's range: load the file to fit it to the view
obj-cannot-read = cannot read { $path }: { $error }
obj-not-a-file = { $path } is not a regular file
obj-too-large = { $path } is { $size }; phonglab reads OBJ files of at most { $max } (about { $millions } million triangles)
obj-over-budget = { $count ->
        [one] { $triangles } triangle takes
       *[other] { $triangles } triangles take
    } { $bytes } to read, more than the memory budget of { $budget } (--memory-budget raises it)
export-flat-unsupported = the PyOpenGL program draws with the scene's generated shaders, which are Gouraud or Phong: choose one of them for the shaded view, not Flat
export-template-broken = the program template { $template } is filled wrongly ({ $problem }): this is a fault of phonglab's; please report it
py-title = { $scene }: the shaded view as phonglab draws it ({ $shading } shading), written by phonglab.
py-usage = Run this file with python3 (a window; needs PyOpenGL, GLUT and NumPy). With --png FILE it draws one 512x512 frame (--size N: NxN), saves it to FILE and exits. The lighting state is set the fixed-function way (glLightfv, glMaterialfv, glLightModel*), and the shaders below compute the whole of OpenGL 2.1's lighting from that state, read from GL each frame: change any of those calls and the picture changes as it would under fixed-function OpenGL, except where a comment beside the call says otherwise.
py-rules-comment = The rule set the shaders were written for: "worksheet", "opengl" or "phong-demo". Only the normal matrix in set_uniforms() reads RULES; the rest of the rule set (the scene's ambient and emission among it) is the shaders' #define lines.
py-shaders-comment = The shaders: the whole of OpenGL 2.1's lighting (per vertex for Gouraud, per fragment for Phong), reading GL's own state: gl_LightSource[], gl_FrontMaterial, gl_BackMaterial, gl_LightModel, and the u_ uniforms that set_uniforms() reads with glGet*. Only the #define lines are this scene's (its rule set's departures from OpenGL); `phonglab shader` prints the scene's specialised shaders instead.
py-projection-orbit = phonglab's orbit camera: gluPerspective(40, 1, 0.1, 100)
py-projection-clip = no projection at all: the picture is clip space itself (the Phong demo's)
py-modelview-comment = the modelview the object is drawn with: the camera, then the object's turn (rows)
py-lighting-modelview-comment = the modelview the lighting uses, where it is not the drawing's (the demo lights in object space)
py-color-material-comment = GL_COLOR_MATERIAL: the material colours it tracks are the current colour (glColor); u_color is that colour
py-normalised-comment = normalised Blinn-Phong: the specular term times (ns + 8)/(8π); fixed-function GL has no such factor, so only the shader below computes it (GL's own lighting from this state would not)
py-light-eye = placed under the identity: the light moves with the eye
py-light-object = placed under the whole modelview: the light turns with the object
py-light-world = placed under the view matrix: the light stays put in the world
py-state-doc = The scene's lighting state, set the fixed-function way. Each light's GL_POSITION and GL_SPOT_DIRECTION are transformed by the modelview current when they are set, so GL keeps them in eye space.
py-reader-doc = Gives the shaders what GLSL has no variable for, read from GL's state each frame: the lighting modelview and the normal matrix, the enabled lights, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_COLOR_CONTROL, GL_NORMALIZE or GL_RESCALE_NORMAL, GL_COLOR_MATERIAL, and GL_SHADE_MODEL.
py-editable-comment = You may edit every call below (a glLight*, glMaterial* or glLightModel* value, glEnable or glDisable of a light, GL_NORMALIZE, GL_COLOR_MATERIAL): the shaders read this state every frame and draw what fixed-function OpenGL draws from it, except where a comment below says otherwise. RULES and the shaders' #define lines are not GL state: they stay as written.
py-lighting-comment = The shaders light the object whether or not GL_LIGHTING is enabled: with glDisable(GL_LIGHTING), fixed-function OpenGL would draw the current colour (glColor) unlit; these shaders would not.
py-scene-ambient-off = SCENE_AMBIENT is 0 under these rules: the shaders add neither this scene ambient nor the material's GL_EMISSION, so editing either changes nothing here (fixed-function OpenGL would add both).
py-object-doc = The object, as phonglab builds it.
py-arrays-comment = phonglab's triangles (positions, normals, and three vertex indices per triangle)
py-teapot-winding = freeglut's teapot is wound clockwise: with two-sided lighting its outside would be lit as the back side
of-header-comment = { $scene }: its lighting in an openFrameworks 0.12 app, written by phonglab. It assumes oF's default renderer: ofSetupOpenGL opens a GL 2.1 window, where ofGLRenderer lights with fixed-function OpenGL (not the programmable renderer of GL 3+).
of-main-comment = The default renderer: GL 2.1, fixed-function lighting (see ofApp.h).
of-source-comment = The scene's lights, material and camera as phonglab has them; oF places lights in world coordinates, under the camera's view only.
of-camera-comment = phonglab's view: gluPerspective(40, 1, 0.1, 100) and its orbit camera
of-light-comment = the scene's light { $index }
of-directional-comment = a directional light's GL_POSITION is its look direction, w = 0
of-spot-comment = the spot direction is the light's look direction
of-material-comment = the material, bound while the object is drawn (ofSetColor under lighting would turn on glColorMaterial instead)
of-back-material-comment = oF has one material for both sides: the back side's, raw GL
of-color-material-comment = GL_COLOR_MATERIAL: the material colours it tracks follow the current colour, which ofSetColor sets
of-normalised-comment = normalised Blinn-Phong: the specular term times (ns + 8)/(8π); fixed-function GL has no such factor, so the app draws with phonglab's generated shader (oF's lights and material only set GL's state)
of-shader-comment = the general shaders (the whole of OpenGL's lighting, read from GL's state), for what fixed-function GL cannot compute: only their #define lines are this scene's rule set; the lights and the material are the oF and GL calls of this app
of-shader-state-comment = what GLSL has no variable for, read from GL's state every frame (the shaders read the lights, the material and the scene's ambient themselves): edit any light, material or light model call and the picture follows
of-no-scene-ambient = this scene's rules have no scene ambient: 0 here, so that GL computes the same I (oF's default is 0.2)
of-rules-comment = phonglab computes this scene under { $rules }; fixed-function GL computes OpenGL's equation, which can differ (the normal by the inverse transpose, the specular gate)
of-phong-specular-comment = this scene's specular is Phong's (R · V); fixed-function GL computes Blinn-Phong (N · H): the highlight differs
of-local-viewer-comment = the local viewer: oF has no call for it
of-two-sided-comment = two-sided lighting: oF has no call for it
of-separate-specular-comment = a separate specular colour: oF has no call for it
of-normal-as-is-comment = ofEnableLighting turns GL_NORMALIZE on; this scene uses normals as transformed
of-normal-rescale-comment = ofEnableLighting turns GL_NORMALIZE on; this scene rescales normals instead
of-eye-light-comment = a light fixed to the eye (a head lamp): oF places lights in the world, so raw GL under the identity modelview, on the next free light
of-spin-comment = the object's turn in phonglab's view
of-cylinder-comment = gluCylinder runs along z; oF's cylinder along y, centred
of-no-teapot-comment = oF has no teapot and reads no mesh file here: a sphere stands in (load your model with ofMesh::load or ofxAssimpModelLoader)
py-normal-matrix-comment = OpenGL: the inverse transpose of the modelview's 3x3; the worksheet: the 3x3 itself.

## compare

shader-step = step { $n }
shader-note-directional-l = directional: one L for every vertex
shader-note-one-h = one H: directional light, infinite viewer
shader-note-spot-cosine = spot cosine
shader-note-cone-test = the cone test
shader-note-alpha = alpha: the diffuse alpha
shader-note-zero-normal = a zero normal has no direction: no diffuse, no specular
shader-note-emission-ambient = emission + scene ambient
shader-note-secondary = the secondary colour
shader-note-projective = the modelview is projective: divide by w
shader-note-translation = the modelview is a translation: its last column
shader-note-affine = affine modelview: w = 1, no division
shader-note-normal-by-m = the worksheet: M itself
shader-header = phonglab: { $what }, { $shading } shading, generated from the specialised plan.
    Only the stages this scene's key calls for; comments give the worked calculation's steps.
shader-what-vertex-lighting = the vertex lighting
shader-what-program = The program
shader-what-program-fragment = The program per fragment
shader-what-fragment-vertex-stage = the per-fragment lighting's vertex stage
shader-what-fragment-lighting = the per-fragment lighting
shader-vertex-shader = vertex shader
shader-fragment-shader = fragment shader

## sheets

exercise-modelview = rotate { $degrees } degrees about { $axis }, then translate { $translation }
exercise-name = exercise { $number } (seed { $seed })
sheet-rules-worksheet = the worksheet's rules (no scene ambient, no emission, M itself for normals)
sheet-rules-opengl = the rules of OpenGL 2.1's fixed function
sheet-rules-demo = the rules of the Phong demo's shader
sheet-compute = Compute the colour of the vertex step by step, under { $rules }.
sheet-colours = Colours are written as the worksheet writes them, [r g b 0], so every product of two colours has 0 as its fourth component.
sheet-vertex = The vertex
sheet-modelview = The modelview
sheet-direction = direction (w = 0)
sheet-position = position
sheet-light-world = { $what }, in world coordinates: transform it by the modelview
sheet-degrees = { $value } degrees
sheet-material = Material: { $name }
sheet-light-model = The light model
yes = yes
no = no
sheet-compute-heading = Compute
exercise-effect-positional = a positional light
exercise-effect-attenuation = attenuation
exercise-effect-spot = a spotlight
exercise-effect-local-viewer = the local viewer
exercise-effect-two-sided = two-sided lighting
exercise-effect-several-lights = several lights

## moodle-exam

exam-modelview = rotate about { $axis } by the angle whose cosine is { $cos } and sine { $sin }, then translate { $translation }
exam-name = exam exercise { $number } (seed { $seed })
exam-material = chosen for this exam
exam-no-calculator = No calculator.
exam-by-hand = Every value works out by hand and exactly: carry it exact into the next step, and round only the value you write down.
moodle-digits-quiz = Each field asks for the significant digits in brackets; an answer within { $percent } % of the value (or { $near_zero } near 0) is right.
moodle-digits-exam = Give each value rounded to { $digits } significant digits.
moodle-carry = Carry each value into the next step as you computed it, not rounded: round only what you type in a field.
moodle-decimal-mark = Numbers may be typed with a decimal comma or a decimal point: Moodle accepts both.
moodle-part-digits = { $digits ->
    [one] one significant digit
   *[other] { $digits } significant digits
}
moodle-right = Right: { $formula }
moodle-picture-feedback = The picture on the left is drawn with { $right }; the one on the right with { $wrong }.
moodle-wrong = Not right. { $formula }: it depends on { $inputs }; check those values first.
moodle-front-side = Lighting is two-sided: compute the front side, the one the vertex normal faces (the back side takes -n).
moodle-takes-givens = the givens
moodle-general-feedback = Each field's feedback gives its step's formula; the worked calculation of every step is in your teacher's key to this variant.
moodle-picture-right = Drawn right
moodle-picture-wrong = Drawn with one mistake
moodle-picture-question = Which one mistake makes the right-hand picture?
moodle-choice-not = Not this one. This mistake would change the picture in another way: { $why }

## cli-out

channel-emission = Emission
channel-scene-ambient = Scene ambient
channel-ambient = Ambient
channel-diffuse = Diffuse
channel-specular = Specular
channel-attenuation = 1/at (attenuation factor)
channel-spot = Spot factor
channel-n-dot-l = N·L
channel-n-dot-h = N·H
channel-r-dot-v = R·V
channel-normal = Normal as a colour
channel-light-count = Lights reaching
probe-pixel = Pixel ({ $x }, { $y }), { $shading }
probe-triangle = triangle { $triangle }, vertices { $a }, { $b }, { $c }
probe-front-face = front face (counter-clockwise on the screen)
probe-back-face = back face (clockwise on the screen)
probe-weights = Perspective-correct weights
probe-vertex-colours = Vertex colours (each clamped at its vertex, as OpenGL does)
probe-vertex-colours-unclamped = Vertex colours (a shader’s varying: not clamped)
probe-vertex = vertex { $vertex }
probe-weighted-sum = Weighted sum
probe-normal-interpolated = Interpolated normal, before normalising
probe-normal-length = its length
probe-normal = Normal the fragment is lit with
probe-normal-as-interpolated = Normal used as interpolated (this shader does not normalise it)
probe-position = Interpolated position (eye space)
probe-flat-centroid = Face lit once, at its centroid (eye space)
probe-flat-normal = with its plane’s normal
probe-provoking = OpenGL’s GL_FLAT would take the last vertex’s colour, vertex { $vertex }
probe-terms = Terms at the pixel
probe-terms-interpolated = Terms at the pixel (the vertices’ terms, interpolated)
probe-light = Light { $index }
probe-terms-sum = Sum of the terms (no clamp)
probe-unclamped = Colour that reached the framebuffer
probe-stored = Stored, clamped and rounded to 8 bits
probe-attenuation-factor = Attenuation factor, what the terms are multiplied by

## io-errors

write-step-create-staging = create a staging folder in
write-step-list = list
write-step-lock-folder = lock the folder
write-step-recover = finish the set a stopped run left in
write-step-remove-journal = remove the journal of
write-step-killed = stop (killed) while writing
write-kept-folder = the folder is unchanged
write-kept-recoverable = the old set or the new one is whole, and the next run in this folder finishes what was started
write-kept-staging = nothing was deleted: the files that could not be put back in place are kept in phonglab's working folder in it (.phonglab-set…), and the next run in this folder puts them back or says where they are

## errors

error-out-of-range = { $field } = { $value } is out of range: allowed { $allowed }
error-not-finite = { $field } must be a finite number, not { $value }
error-too-many-lights = { $count } lights: OpenGL has at most { $max }
error-camera-mismatch = the scene's view matrix is not the one its camera gives ({ $camera }): set the camera, or give the matrix as a typed camera
error-zero-attenuation = { $field }: constant, linear and quadratic attenuation are all 0, so the light would be infinitely bright; make at least one positive
allowed-spot-cutoff = [0, 90], or 180 for no spotlight
allowed-float = a float: 0, or 1.2e-38 <= |x| <= 3.4e38
allowed-mview = 1, 2, 3, 4 or 5
allowed-look-at = an eye away from the centre, with up not along the view direction
allowed-pixel = at least 1 pixel
toml-place = line { $line }, column { $column }
toml-unknown-field = unknown field { $field }, expected one of { $known }
toml-did-you-mean = did you mean { $field }?
toml-missing-field = missing field { $field }
toml-invalid-type = invalid type: { $found }, expected { $expected }
toml-kind-number = a number
toml-kind-number-value = the number { $value }
toml-kind-text = the text { $value }
toml-kind-a-text = a text (in quotes)
toml-kind-boolean = true or false
toml-camera-takes = { $field }: a camera of kind = "{ $kind }" takes { $keys }
toml-camera-needs = camera: kind = "{ $kind }" needs { $keys }
toml-unknown-material = { $field }: unknown material { $name }; the classic materials are { $names }
toml-placement-needs-matrix = { $field }: placement = "matrix" needs placement_matrix (4 rows of 4)
toml-matrix-needs-placement = { $field }: placement_matrix needs placement = "matrix"
toml-control-character = { $field } holds the control character { $char } (character { $position }): a name or a path is one line of printable text
toml-unknown-field-one = unknown field { $field }, expected { $known }

## limits

limit-light-at-vertex = the light is at the vertex: L has no direction, so no diffuse or specular; its ambient stays, attenuated at d = 0
limit-light-direction-zero = the directional light's direction is (0, 0, 0): L has no direction, so no diffuse or specular; its ambient stays
limit-halfway-zero = L is exactly opposite V, so H = L + V = 0 has no direction: no specular
limit-zero-normal = the normal is zero: no diffuse or specular
limit-normal-scaled = |n|^2 under- or overflows in this precision: n was divided by its largest component before normalising
limit-distance-scaled = |VP|^2 under- or overflows in this precision: d was computed by scaling VP by its largest component first
limit-attenuation-infinite = k0 + k1 d + k2 d^2 = 0: the light's terms are +infinity where positive and 0 where zero (clamping gives 1 and 0)
limit-spot-direction-zero = the spot direction is (0, 0, 0): the cone has no axis, so the spot factor is 0
limit-spot-at-vertex = the spotlight is at the vertex: there is no direction to test against the cone, so the spot factor is 0
limit-vertex-at-eye = the vertex is at the eye (local viewer): V has no direction, so no specular
limit-vertex-at-infinity = the vertex has w = 0 (a point at infinity): L points away from it towards positional lights, and d is infinite
limit-singular-modelview = the modelview's 3x3 part is singular: normals go through its cofactor matrix, which keeps their direction only
limit-infinities-cancelled = an infinite term of one sign met one of the other sign: the sum is undefined and shown as 0

## cost

cost-approx-llvmpipe-pow = llvmpipe pow
cost-approx-schlick-pow = Schlick pow
cost-approx-fast-rsqrt = fast rsqrt
cost-approx-no-renormalisation = no renormalisation

## plan

effect-normalisation = normalisation
effect-position = eye-space position P
effect-view-vector = view vector V
effect-scene-colour = emission and scene ambient
effect-back-side = back side
effect-light-vector = light vector L and distance d
effect-attenuation = attenuation
effect-spotlight = spotlight
effect-halfway = halfway vector H
effect-reflection = reflection vector R
effect-specular-power = specular power
why-normalise-off = GL_NORMALIZE and GL_RESCALE_NORMAL are off
why-rescale-one = GL_RESCALE_NORMAL is on but its factor is exactly 1 (the modelview preserves lengths)
why-normalize-on = GL_NORMALIZE is on
why-rescale-on = GL_RESCALE_NORMAL is on
why-renormalised = interpolated normals are renormalised
why-position-translation = P = p + t; the modelview is a translation (its 3x3 part is the identity), so the rows' products and the division by w are skipped: three additions
why-position-affine = P = M p; the modelview is affine (last row 0 0 0 1), so w = 1 and the division by w is skipped
why-position-projective = P = M p / w: the modelview is projective, w varies per vertex
why-position-eye = the vertices arrive in eye space: nothing to transform
why-position-unread = no positional light and V is one constant (infinite viewer): nothing reads P
why-v-local = local viewer: V = normalize(-P) per vertex, in f64; a chunk of { $chunk } vertices whose coordinates all lie within 2^-400..2^400 skips the power-of-two scaling before squaring (there it changes no bit)
why-v-worksheet = the worksheet's V = normalize(obs - P), obs = P (1, 1, 0, 1): (0, 0, -sign(P.z)) per vertex
why-v-infinite = infinite viewer: V = (0, 0, 1) for every vertex
why-scene-added = added as one constant per side
why-scene-zero = both are zero (or the rule set leaves them out): nothing is added
why-two-sided = two-sided lighting: -n and the back material
why-one-sided = one-sided lighting: the back colour is the front's
why-l-positional = positional light: per vertex, in f64; a chunk of { $chunk } vertices whose VP components all lie within 2^-400..2^400 skips the power-of-two scaling before squaring (there it changes no bit)
why-l-directional = the light is directional: L is one constant, there is no d
why-attenuation-on = 1/(k0 + k1 d + k2 d^2) per vertex
why-attenuation-directional = the light is directional
why-attenuation-one = factors (1, 0, 0) give 1
why-spot-on = cone test and exponent per vertex
why-spot-directional = the light is directional: its spot factor is one constant, computed once
why-spot-none = cutoff 180: not a spotlight
why-per-vertex = per vertex
why-h-constant = directional light and infinite viewer: H = normalize(L + V) is one constant
why-specular-zero = light specular x material specular is zero
why-power-on = max(cos, 0)^shininess per vertex
why-power-none = no specular term
why-power-zero = shininess 0: max(cos, 0)^0 = 1

## materials

material-name-emerald = emerald
material-name-jade = jade
material-name-obsidian = obsidian
material-name-pearl = pearl
material-name-ruby = ruby
material-name-turquoise = turquoise
material-name-brass = brass
material-name-bronze = bronze
material-name-chrome = chrome
material-name-copper = copper
material-name-gold = gold
material-name-silver = silver
material-name-black-plastic = black plastic
material-name-cyan-plastic = cyan plastic
material-name-green-plastic = green plastic
material-name-red-plastic = red plastic
material-name-white-plastic = white plastic
material-name-yellow-plastic = yellow plastic
material-name-black-rubber = black rubber
material-name-cyan-rubber = cyan rubber
material-name-green-rubber = green rubber
material-name-red-rubber = red rubber
material-name-white-rubber = white rubber
material-name-yellow-rubber = yellow rubber

## phonglab diagnose: a student's picture checked

diagnose-normalize-off = GL_NORMALIZE left off under a modelview that scales: the normals are not of length 1
diagnose-viewer-swapped = The local and the infinite viewer swapped (GL_LIGHT_MODEL_LOCAL_VIEWER the other way)
diagnose-flipped-normals = The normals point inwards (flipped)
diagnose-two-sided-off = Two-sided lighting off: the back faces are lit with the front's normals
diagnose-two-sided-on = Two-sided lighting on where the scene has it off (GL_LIGHT_MODEL_TWO_SIDE true): the back faces are lit with their own normals and the back material, not with the front's
diagnose-attenuation-left-out = The attenuation left out
diagnose-spot-left-out = The spotlight's cone left out (cutoff 180)
# diagnose: picture mistakes
diagnose-shininess-fraction = The shininess given as the 0–1 value of a material table instead of that value times 128 ({ $fraction } for { $shininess-given }): a highlight spread over the whole object
diagnose-light-left-out = Light { $light } (GL_LIGHT{ $light }) left out: glEnable(GL_LIGHT{ $light }) missing
diagnose-point-as-directional = Light { $light } (GL_LIGHT{ $light }) given w = 0 in GL_POSITION: a directional light instead of a point light
diagnose-light-ambient-left-out = The ambient colour of light { $light } (GL_LIGHT{ $light }) left at OpenGL's default (0, 0, 0, 1)
diagnose-specular-left-out = The material's specular colour left at OpenGL's default (0, 0, 0, 1): no highlight
diagnose-diffuse-specular-swapped = The material's diffuse and specular colours exchanged
diagnose-emission-added = A constant colour, about { $emission }, added where the object is lit or not: an emission (GL_EMISSION) the scene does not have, or more ambient
diagnose-colours-differ = The picture's colours are those of other values (in each term, the light's colour times the material's): { $terms }
diagnose-term-scene = the light that is the same everywhere (the scene's ambient, and the ambient of each light neither attenuated nor a spot, times the material's ambient, plus the emission)
diagnose-term-ambient = GL_LIGHT{ $light }'s ambient
diagnose-term-diffuse = GL_LIGHT{ $light }'s diffuse
diagnose-term-specular = GL_LIGHT{ $light }'s specular
diagnose-term-differs = { $term }: { $shown } in the picture, { $scene } in the scene
diagnose-materials-differ = The picture's materials are other colours than the scene's on a side (two-sided lighting, each side its own material): { $colours }
diagnose-side-front = of the front
diagnose-side-back = of the back
diagnose-material-colour-differs = { $name } { $which }: { $shown } in the picture, { $scene } in the scene
diagnose-material-shininess-differs = GL_SHININESS { $which }: { $shown } in the picture, { $scene } in the scene
diagnose-spot-cutoff-doubled = The spot cutoff of light { $light } (GL_LIGHT{ $light }) doubled: the cone's full angle given where GL_SPOT_CUTOFF takes its half angle
diagnose-normal-matrix-not-transposed = The normals transformed by the inverse of the modelview's 3x3 (np.linalg.inv(m3)) where OpenGL takes its inverse transpose: under a rotation they turn the wrong way
diagnose-normal-not-transformed = The normals left in object space (not transformed by the modelview's normal matrix): the object is lit as if it had not turned
diagnose-depth-test-off = The depth test left out (no glEnable(GL_DEPTH_TEST)): each triangle covers the ones drawn before it, so the far side of the object shows over the near side where it is drawn later
diagnose-quadric-inside = The quadric turned inside out (gluQuadricOrientation(GLU_INSIDE)): its normals point inwards and its faces face inwards, so the lit side faces away from the light
diagnose-light-after-model-light = Light { $light } (GL_LIGHT{ $light }) given under the modelview the object is drawn with (view × model) instead of its own matrix: it moves with the object
diagnose-spot-cutoff-differs = The spot cutoff of light { $light } (GL_LIGHT{ $light }, GL_SPOT_CUTOFF) looks like { $cutoff }° in the picture; the scene gives { $cutoff-scene }°
diagnose-spot-exponent-differs = The spot exponent of light { $light } (GL_LIGHT{ $light }, GL_SPOT_EXPONENT) looks like { $exponent } in the picture; the scene gives { $exponent-scene }
diagnose-attenuation-constant-differs = The constant attenuation of light { $light } (GL_LIGHT{ $light }, GL_CONSTANT_ATTENUATION) looks like { $constant } in the picture; the scene gives { $constant-scene }
diagnose-attenuation-linear-differs = The linear attenuation of light { $light } (GL_LIGHT{ $light }, GL_LINEAR_ATTENUATION) looks like { $linear } in the picture; the scene gives { $linear-scene }
diagnose-attenuation-quadratic-differs = The quadratic attenuation of light { $light } (GL_LIGHT{ $light }, GL_QUADRATIC_ATTENUATION) looks like { $quadratic } in the picture; the scene gives { $quadratic-scene }
diagnose-shininess-differs = The shininess (GL_SHININESS) looks like { $shininess } in the picture; the scene gives { $shininess-scene }
diagnose-value-negligible = { $least } or more (the light is negligible: nothing of it reaches the object)
diagnose-attenuation-left-out-light = The attenuation of light { $light } (GL_LIGHT{ $light }) left out
diagnose-spot-direction-untransformed = The spot direction of light { $light } (GL_LIGHT{ $light }) given before the camera transform (under the identity), its position after it
diagnose-light-after-model = The lights placed in the world given after the model transform (under view × model instead of the view): they turn with the object
diagnose-headlight-under-view = Light { $light } (GL_LIGHT{ $light }), fixed to the eye, given under the view transform instead of the identity: placed in the world
diagnose-light-before-view-light = Light { $light } (GL_LIGHT{ $light }) placed before the camera: its GL_POSITION given under the identity, not the view transform, so it moves with the eye
diagnose-colour-material-off = GL_COLOR_MATERIAL not enabled: the object is lit with the glMaterial colours, not the current colour
diagnose-colour-material-diffuse-only = glColorMaterial tracking GL_DIFFUSE only instead of GL_AMBIENT_AND_DIFFUSE: the ambient stays the glMaterial one
diagnose-spot-cutoff-halved = The spot cutoff of light { $light } (GL_LIGHT{ $light }) halved: the cone's full angle given where GL_SPOT_CUTOFF takes its half angle
diagnose-spot-cutoff-radians = The spot cutoff of light { $light } (GL_LIGHT{ $light }) given in radians (math.radians): OpenGL takes GL_SPOT_CUTOFF in degrees
diagnose-spot-exponent-ignored = The spot exponent of light { $light } (GL_LIGHT{ $light }) left out (0): a hard-edged pool of light
diagnose-spot-cutoff-exponent-swapped = The spot cutoff and the spot exponent of light { $light } (GL_LIGHT{ $light }) exchanged
diagnose-spot-direction-reversed = The spot direction of light { $light } (GL_LIGHT{ $light }) reversed: pointing from the target to the light
diagnose-attenuation-terms-swapped = The linear and quadratic attenuation of light { $light } (GL_LIGHT{ $light }) exchanged
diagnose-attenuation-constant-left-out = The constant attenuation of light { $light } (GL_LIGHT{ $light }) set to 0 (as if 0 meant no attenuation)
diagnose-directional-as-point = Light { $light } (GL_LIGHT{ $light }) given w = 1 in GL_POSITION: a point light instead of a directional light
diagnose-diffuse-back-only = The material's diffuse colour given for GL_BACK only: the front faces keep OpenGL's default (0.8, 0.8, 0.8)
diagnose-ambient-back-only = The material's ambient colour given for GL_BACK only: the front faces keep OpenGL's default (0.2, 0.2, 0.2)
diagnose-specular-back-only = The material's specular colour and shininess given for GL_BACK only: the front faces keep OpenGL's defaults (no highlight)
diagnose-material-back-only = Every glMaterial call given for GL_BACK only: the front faces keep OpenGL's default material
diagnose-light-colour-0-255 = The diffuse colour of light { $light } (GL_LIGHT{ $light }) given in 0..255 instead of 0..1
diagnose-row-vectors = The lights' modelview loaded transposed (NumPy's rows given to glLoadMatrixf as columns)
diagnose-light-ambient-from-diffuse = The ambient colour of light { $light } (GL_LIGHT{ $light }) copied from its diffuse colour
diagnose-ambient-from-diffuse = The material's ambient given its diffuse colour (GL_AMBIENT_AND_DIFFUSE)
diagnose-specular-from-colour = The material's specular colour given the object's colour: a coloured highlight
diagnose-emission-left-out = The material's emission left at black (0, 0, 0, 1)
diagnose-row-vectors-light = The modelview of light { $light } (GL_LIGHT{ $light }) loaded transposed (NumPy's rows given to glLoadMatrixf as columns)
diagnose-emission-from-colour = The material's emission given the object's colour: the object glows in its own colour
diagnose-ambient-diffuse-swapped = The material's ambient and diffuse colours exchanged
diagnose-light-diffuse-left-out = The diffuse colour of light { $light } (GL_LIGHT{ $light }) never set: OpenGL's default, white for GL_LIGHT0 and black for the others
diagnose-diffuse-not-clamped = In the shader, the diffuse term takes N·L without max(N·L, 0): where the light is behind the surface it subtracts light
diagnose-vlv-reversed = In the shader, the light vector L points from the light to the surface (P − light position) instead of from the surface to the light
diagnose-viewer-reversed = In the shader, the local viewer's V points from the eye to the point (normalize(P)) instead of towards the eye (normalize(−P))
diagnose-halfway-not-normalised = In the shader, the halfway vector L + V is not normalised before its dot product with N
diagnose-flat-shade-model = glShadeModel(GL_FLAT) instead of GL_SMOOTH: each face has one colour, the colour lit at its last vertex
diagnose-view-order-reversed = The object's modelview multiplied in the wrong order (rotation × translation instead of translation × rotation): the object is drawn and lit away from its place
diagnose-view-order-reversed-lights = The view matrix multiplied in the wrong order (rotation × translation instead of translation × rotation), for the object and the lights placed under it
diagnose-view-order-reversed-lights-only = The lights' view matrix multiplied in the wrong order (rotation × translation instead of translation × rotation): the lights placed in the world are placed wrongly; the object is drawn right
diagnose-shininess-refused = GL_SHININESS given over 128 (a 0–1 value multiplied by 128 twice, or a 0–1000 scale): OpenGL refuses the call (GL_INVALID_VALUE) and the shininess stays at its default, 0: the specular colour spread over the whole lit side
diagnose-directional-reversed = The direction of light { $light } (GL_LIGHT{ $light }) reversed: GL_POSITION (x, y, z, 0) given as the direction the light travels instead of the direction towards the light, so the object is lit from the opposite side
diagnose-scene-ambient-default = The scene's ambient light (glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ...)) never set: OpenGL's default (0.2, 0.2, 0.2, 1)
diagnose-light-specular-left-out = The specular colour of light { $light } (GL_LIGHT{ $light }) never set: OpenGL's default, white for GL_LIGHT0 and black for the others
diagnose-light-ambient-diffuse-swapped = The ambient and diffuse colours of light { $light } (GL_LIGHT{ $light }) swapped
diagnose-light-diffuse-on-previous = The diffuse colour of light { $light } given to GL_LIGHT{ $previous } (a copied block whose light number was not changed): GL_LIGHT{ $previous } takes it and GL_LIGHT{ $light } keeps OpenGL's default
diagnose-light-specular-on-previous = The specular colour of light { $light } given to GL_LIGHT{ $previous } (a copied block whose light number was not changed): GL_LIGHT{ $previous } takes it and GL_LIGHT{ $light } keeps OpenGL's default
diagnose-positions-as-normals = The vertex positions given as normals (glNormal3fv(position)): each normal points from the object's centre and its length is the point's distance (the radius, on a sphere), which lights it wrongly without GL_NORMALIZE
diagnose-colour-material-ambient-and-diffuse = glColorMaterial tracking GL_AMBIENT_AND_DIFFUSE instead of GL_DIFFUSE only: the current colour replaces the material's ambient too
diagnose-colour-material-wrong-face = glColorMaterial given the wrong face (GL_BACK for GL_FRONT, or the other way round): the faces seen keep the glMaterial colours instead of the current colour
diagnose-spot-cutoff-cosine = The spot cutoff of light { $light } (GL_LIGHT{ $light }) given as its cosine (math.cos(math.radians(…)), about 0.99): OpenGL takes GL_SPOT_CUTOFF in degrees, so the cone is less than one degree wide
diagnose-material-front-only = Two-sided lighting with the glMaterial calls given for GL_FRONT only: the back faces keep OpenGL's default material
diagnose-emission-back-only = The material's emission given for GL_BACK only: the front faces keep OpenGL's default, black
diagnose-material-diffuse-0-255 = The material's diffuse colour given in 0..255 instead of 0..1 ({ $diffuse-levels } for { $diffuse-given }): the diffuse term saturates wherever the light reaches
diagnose-material-colours-0-255 = The material's colours (ambient, diffuse, specular) given in 0..255 instead of 0..1: the object saturates
diagnose-light-not-normalised = In the shader, a positional light's L is not normalised (L = light − P without dividing by its length d): N·L and the spot's cosine grow with the distance
diagnose-reflection-reversed = In the shader, R reflected the wrong way (reflect(L, N) instead of reflect(-L, N)): the highlight appears on the opposite side from where it belongs
diagnose-rescale-for-normalize = GL_RESCALE_NORMAL enabled where GL_NORMALIZE is needed: under a scale that is not uniform the normals are rescaled but not made unit length
diagnose-same-picture = These causes draw the same picture, so it cannot tell them apart (the most common first): { $ids }. Check which one the program holds.
diagnose-same-picture-fitted = These causes draw the same picture, so it cannot tell them apart (the most common first, a changed value before a value fitted from the picture): { $ids }. Check which one the program holds.
diagnose-light-unseen = Nothing of light { $light } (GL_LIGHT{ $light }) reaches the object: the picture is the scene lit without it.
diagnose-nothing-drawn = nothing of the object is drawn: the picture is only the background. Check the draw call (glutSolidTeapot, gluSphere…) and that it runs, and the camera (gluLookAt, gluPerspective): the object may be behind it or outside its view.
diagnose-outline-differs = the object's outline is not this scene's ({ $share } of it differs, beyond a pixel): is this the picture of this scene? Check --scene, and the program's object and camera.
diagnose-region-differs = a region of { $pixels } pixels around ({ $x }, { $y }) differs from the right picture (the right picture explains { $score } of the object's pixels): something is drawn over the object there, or that part of it is wrong. Check what the program draws after the object, and the lighting of that part (its normals, its material).
diagnose-offset-darker = the { $pixels } pixels of the object from ({ $x0 }, { $y0 }) to ({ $x1 }, { $y1 }) are evenly darker than in the right picture, by { $levels } levels on average (noise, a lossy saving or a pixel's shift leave less than { $least }) (the right picture explains { $score } of the object's pixels): something is painted over the object there, or its light or material is a little off. Check what the program draws after the object, and compare its glLight*/glMaterial* values with the scene's.
diagnose-offset-lighter = the { $pixels } pixels of the object from ({ $x0 }, { $y0 }) to ({ $x1 }, { $y1 }) are evenly lighter than in the right picture, by { $levels } levels on average (noise, a lossy saving or a pixel's shift leave less than { $least }) (the right picture explains { $score } of the object's pixels): something is painted over the object there, or its light or material is a little off. Check what the program draws after the object, and compare its glLight*/glMaterial* values with the scene's.
diagnose-marks-differ = thin marks of { $pixels } pixels, from ({ $x0 }, { $y0 }) to ({ $x1 }, { $y1 }), differ from the right picture (the right picture explains { $score } of the object's pixels): lines or marks are drawn over the object there. Check what the program draws after the object (text, axes, a cursor), and save its PNG before anything is drawn on it.
diagnose-levels-darker = the whole picture is { $levels } levels darker on the mean than the right one, and the right picture with its levels so changed explains it as well as any mistake does ({ $score } of the object's pixels). A change of the saved picture's gamma, brightness or colour profile does this, and a mistake in the lighting may hide under it: save the program's PNG unchanged (with its --png option) and check it again.
diagnose-levels-lighter = the whole picture is { $levels } levels lighter on the mean than the right one, and the right picture with its levels so changed explains it as well as any mistake does ({ $score } of the object's pixels). A change of the saved picture's gamma, brightness or colour profile does this, and a mistake in the lighting may hide under it: save the program's PNG unchanged (with its --png option) and check it again.
diagnose-footprint = This mistake changes the right picture by at most { $most } levels; by more than { $tolerance } levels, past a pixel's shift, only in { $pixels } pixels: { $groups }. That is too few for the share to show it; there your picture is the mistake's: it is { $mistake } levels from the mistake's picture on average, and { $right } from the right one.
diagnose-footprint-group = { $count } from ({ $x0 }, { $y0 }) to ({ $x1 }, { $y1 })
diagnose-footprint-rest = { $count } elsewhere
diagnose-footprint-and = and
diagnose-verdict-right-lossy = Right, with losses: the right picture explains { $score } of the object's pixels within { $levels } levels of a blend of their neighbours ({ $strict } within { $tolerance } of a neighbour), and what differs is noise (as a JPEG saving, a resize, a blur or a camera leaves), not a change of the picture that it shows. A value a little off (a spot exponent 9 for 8) may hide in the losses; the numbers the program prints can tell (phonglab check).
diagnose-looks-jpeg = The picture looks saved as JPEG: its difference from the right picture jumps across the edges of 8 x 8 blocks ({ $ratio } times as much as inside them). A lossy saving changes every pixel a little and may hide the cause: save the picture as PNG straight from the program (the exported program's --png option) and diagnose that one.
diagnose-evenly-off = The picture is not the right one with losses only: over the { $width } x { $width } pixels from ({ $x0 }, { $y0 }) its { $channel ->
        [0] red
        [1] green
       *[2] blue
    } is { $levels } levels off the right picture's on average, { $errors } standard errors beyond what half a pixel's shift makes there; noise and a lossy saving scatter such a mean about 0. A value of the scene (a colour, an attenuation, the shininess) may be a little off there, or the picture moved by more than half a pixel, and the losses may hide which: save the picture as PNG straight from the program (the exported program's --png option) and diagnose that one.
diagnose-verdict-right-within = Right within what a picture can tell: the right picture explains { $score } of the object's pixels (a pixel's shift and { $tolerance } levels allowed), but inside the object your picture differs from it by up to { $most } levels, { $pixels } pixels by more than { $rounding }. A mistake that changes the picture by no more than that (a shininess or a colour a little off) looks the same: this verdict cannot rule it out. The program's numbers can: check the values the notebook prints with phonglab check, or compare the program's glLight*/glMaterial* values with the scene's.
diagnose-verdict-right = Right: the right picture explains { $score } of the object's pixels, and inside the object yours is that picture to the rounding ({ $rounding } level), as another OpenGL draws it. A value so little off that it moves no pixel further cannot show in a picture; the numbers the program prints can (phonglab check).
diagnose-verdict-wrong = Wrong. The cause: { $cause } ({ $id }); the picture with that mistake explains { $score } of the object's pixels, the right picture { $right }.
diagnose-verdict-wrong-nearer = Wrong. The cause: { $cause } ({ $id }). The picture with that mistake and the right picture both explain { $score } of the object's pixels within the tolerance, but where the two differ ({ $pixels } pixels) yours is { $fitted } levels from the first on average (root mean square) and { $scene } from the right one.
diagnose-verdict-wrong-nearer-inside = Wrong. The cause: { $cause } ({ $id }). The picture with that mistake and the right picture both explain { $score } of the object's pixels within the tolerance, but inside the object yours is { $fitted } levels from the first on average (the three channels summed) and { $scene } from the right one.
diagnose-verdict-wrong-or = Wrong. The cause: { $cause } ({ $id }) or { $other } ({ $other-id }){ $more ->
        [0] {""}
        [one] , or one more listed below
       *[other] , or one of { $more } more listed below
    }: the picture cannot tell which; each of these mistakes explains { $score } of the object's pixels, the right picture { $right }.
diagnose-unexplained-said = Unexplained: { $finding }
diagnose-difference-said = each channel's |A − B| × { $gain }: black where the two pictures agree, full strength (255) from a difference of { $full } { $full ->
        [one] level
       *[other] levels
    } on; the largest difference here, { $largest } { $largest ->
        [one] level
       *[other] levels
    }, is drawn at { $drawn }/255{ $boxes ->
        [0] .
        [one] . A dashed magenta box marks the place the diagnosis names.
       *[other] . Dashed magenta boxes mark the { $boxes } places the diagnosis names.
    }
diagnose-also = It also explains the picture: { $cause } ({ $id }), { $score }.
diagnose-verdict-unexplained = No mistake phonglab knows explains this picture: the right picture explains { $right } of the object's pixels. The closest mistake, not named as the cause ({ $id }, { $score }): { $cause }.
diagnose-verdict-unexplained-none = No mistake phonglab knows explains this picture: the right picture explains { $right } of the object's pixels.
diagnose-where = Pixels are counted from (0, 0) at the top left, y down, as the PNG's rows are (glReadPixels counts from the bottom left).

## phonglab check: a student's work checked

check-no-outputs = this notebook was saved without its outputs: nothing it printed can be checked. Run it first (Jupyter: Kernel → Restart & Run All), save it, and check it again
check-too-many-values = this work prints more than { $count } numbers: it is refused whole rather than checked in part (print only the worksheet's steps)
check-verdict-right = right
check-verdict-right-given = right, given your { $step }
check-verdict-rounding = rounding
check-verdict-wrong = wrong
check-cause-normal-by-modelview = the normal transformed by the modelview M instead of its inverse transpose (wrong under a non-uniform scale)
check-cause-normal-not-normalised = the normal not normalised after its transform
check-cause-light-not-transformed = the light's position not transformed by the modelview (left in object space)
check-cause-light-transformed-twice = the light's position transformed by the modelview twice
check-cause-vectors-cell-run-twice = the normal looks transformed twice, and the vertex and the light with it: the cell that transforms them was run twice. Restart & Run All (Jupyter: Kernel → Restart & Run All)
check-cause-vlv-reversed = vlv reversed: from the light to the vertex instead of from the vertex to the light
check-cause-vlv-not-normalised = vlv not normalised
check-cause-directional-as-point = a directional light (w = 0) treated as a point
check-cause-viewer-swapped = the local and the infinite viewer swapped
check-cause-halfway-not-normalised = H not normalised
check-cause-specular-without-gate = specular computed where the light is behind the surface (the N·L gate left out)
check-cause-diffuse-not-clamped = the diffuse term not clamped: negative where the angle passes 90 degrees
check-cause-acos-past-one = acos of a cosine just past 1 (rounding): limit it to [-1, 1] first
check-cause-spot-cutoff-radians = the spot cutoff's cosine taken of degrees as if they were radians
check-cause-spot-exponent-outside-cone = the spot exponent applied outside the cone too
check-cause-attenuation-multiplied = the light multiplied by the attenuation instead of divided
check-cause-attenuation-object-distance = the attenuation's distance measured in object space
check-cause-w-divide-forgotten = the division by w forgotten
check-cause-shininess-fraction = the shininess as the 0–1 fraction instead of times 128
check-cause-for-light = { $cause } (light { $light })
check-cause-normal-matrix-with-translation = the normal transformed by the inverse transpose of the whole 4x4 modelview: its translation gives the normal a w that enters its length
check-cause-normal-not-transformed = the normal not transformed to eye space at all
check-cause-vertex-not-transformed = the vertex position not transformed by the modelview (left in object space)
check-cause-point-as-directional = a positional light treated as directional: vlv taken from its position alone
check-cause-viewer-reversed = vov reversed: from the eye to the vertex instead of from the vertex to the eye
check-cause-light-ambient-left-out = the light's ambient term left out of its contribution
check-cause-ambient-times-cosine = the ambient term multiplied by N·L like the diffuse (ambient light has no direction)
check-cause-colours-mixed-up = a colour of the wrong term (or none) in a product: each term multiplies the light's and the material's colour of that same term
check-cause-cos-theta-with-light-position = cosTheta taken with the light's position instead of the unit vector vlv
check-cause-theta-in-degrees = the angle converted to degrees and compared with pi/2 (radians): the diffuse vanishes past 1.57 degrees
check-cause-reflection-for-halfway = Phong's R·V used where OpenGL uses Blinn-Phong's N·H
check-cause-reflection-reversed = R reversed: L - 2(N·L)N instead of 2(N·L)N - L
check-cause-specular-cosine-not-clamped = the specular cosine not clamped at 0 before the power
check-cause-specular-left-out = the specular term left out of the light's contribution
check-cause-attenuation-left-out = the light's contribution not divided by the attenuation
check-cause-ambient-not-attenuated = the light's ambient term not divided by the attenuation (OpenGL attenuates ambient, diffuse and specular alike)
check-cause-attenuation-constant-left-out = the constant attenuation term left out
check-cause-attenuation-quadratic-not-squared = the quadratic attenuation term multiplied by d instead of d²
check-cause-distance-from-normalised-vlv = the distance taken from the normalised vlv (always 1)
check-cause-distance-squared = the distance squared: the square root left out
check-cause-spot-exponent-ignored = the spot exponent left out: the spot factor is the cosine itself
check-cause-cone-test-inverted = the spot's cone test the wrong way round: lit outside the cone, dark inside
check-cause-spot-angle-reversed = the spot's angle measured with vlv (towards the light) instead of -vlv (from the light)
check-cause-spot-direction-untransformed = the spot direction not transformed to eye space
check-cause-spot-left-out = the spot factor not applied to the light's contribution
check-cause-spot-on-whole-colour = the spot factor applied to the whole colour (emission and scene ambient too)
check-cause-light-left-out = a light's contribution left out of the sum
check-cause-scene-ambient-left-out = the scene's global ambient left out of the sum
check-cause-scene-ambient-without-material = the scene's global ambient not multiplied by the material's ambient
check-cause-emission-twice = the material's emission added twice
check-cause-colour-not-clamped = the colour not clamped to [0, 1]
check-cause-normal-matrix-not-transposed = the normal by the inverse of the modelview's 3x3 without the transpose
check-cause-row-vectors = vectors multiplied as rows (np.matmul(v, mview)): that is the transposed modelview
check-cause-diffuse-angle-not-cosine = the diffuse scaled by the angle theta (in radians) instead of its cosine
check-cause-halfway-with-view-reversed = H = vlv - vov instead of vlv + vov
check-cause-specular-angle-not-cosine = the specular power taken of the angle beta (in radians) instead of its cosine
check-cause-attenuation-terms-swapped = the linear and quadratic attenuation coefficients swapped (atLin*d*d + atQuad*d)
check-cause-spot-cutoff-not-cosine = the spot's cosine compared with the cutoff angle in degrees instead of the cutoff's cosine
check-cause-spot-on-diffuse-only = the spot factor applied to the diffuse term only (OpenGL applies it to the whole contribution of the light)
check-cause-only-last-light = only the last light's contribution in the sum (the loop's variable used after the loop)
check-cause-emission-left-out = the material's emission left out of the sum
check-cause-alpha-from-sum = the colour's alpha taken from a fourth component that is 0 in these cells (I[3], matDif[3]: the colours are written [r g b 0]) instead of the material's diffuse alpha
check-cause-normal-as-point = the normal typed with w = 1 (as a point): the translation moves it
check-cause-light-by-mview = the light transformed by the vertex's modelview mview instead of the one current when it was placed (an eye-fixed light moved with the camera)
check-cause-spot-cutoff-halved = the cutoff taken as the cone's full angle: half of it used
check-cause-spot-not-on-ambient = the spot factor not applied to the light's ambient term
check-cause-attenuation-on-whole-colour = the attenuation dividing the whole colour (emission and scene ambient too)
check-cause-attenuation-on-directional = a directional light (w = 0) attenuated: OpenGL does not attenuate it
check-cause-vov-with-w = vov = -vertexPos normalised with its w (-1) in the length: the view vector is a direction, its w is 0
check-cause-specular-test-in-degrees = the specular's angle test compares beta in radians with 90 (degrees): it never cuts the specular off
check-cause-specular-times-cosine = the specular also multiplied by N·L (only the diffuse is)
check-cause-shininess-as-product = the shininess as a factor (cosBeta*ns) instead of a power (cosBeta**ns)
check-cause-distance-without-w-divide = the distance from the light's position not divided by its w (vlv is)
check-cause-scene-ambient-wrong-material = the scene's global ambient multiplied by the material's diffuse or specular colour instead of its ambient
check-cause-ambient-outside-share = the light's ambient term outside both the spot factor and the attenuation
check-cause-scene-ambient-times-light = the scene's global ambient also multiplied by the light's ambient colour
check-cause-specular-of-diffuse-cosine = the specular's power taken of the diffuse cosine (cosTheta**ns) instead of N·H
check-cause-spot-exponent-as-factor = the spot exponent as a factor (cosSpot*spotCoef) instead of a power
check-cause-attenuation-inverted = the attenuation inverted (at = 1/(...)) and then divided by: the light multiplied by the denominator
check-run-stopped = not checked: the run stopped with an error before the end: { $error }
check-nothing-compared = not checked: nothing it printed is a step of the worksheet; print each value as the worksheet does, print("vlv = ", vlv)
check-unreadable-steps = not checked whole: these steps were printed with values that are not numbers as NumPy or Python prints them ({ $names }); print each value alone
check-missing-steps = not checked: the notebook holds no value for { $names }: a cell was skipped or stopped with an error. Run every cell (Jupyter: Kernel → Restart & Run All), then this one
check-incomplete = incomplete: { $steps }
check-not-printed = the worksheet asks for { $count ->
        [one] a step this work does not print: { $names }
       *[other] { $count } steps this work does not print, the first { $first }: { $names }
    }. Run every cell (Jupyter: Restart & Run All, in the Kernel menu), print each step as the worksheet does (print("vlv = ", vlv)), and check it again
check-stale-outputs = not checked whole: the outputs are not from one run in order (a cell numbered [{ $later }] below one numbered [{ $earlier }]: a cell was run again, or out of order). Run every cell again (Jupyter: Restart & Run All, in the Kernel menu), save, and check it again
check-after-error = printed after the error, so by an earlier run (Run All stops at an error), and not checked: { $names }
# fix57b
py-shade-model-comment = glShadeModel(GL_SMOOTH) draws the shading this program was written for (Gouraud: the vertices' colours interpolated; Phong: each pixel lit). With GL_FLAT the shaders draw what fixed-function OpenGL draws: each face in the colour lit at its provoking vertex (a triangle’s or a quad’s last vertex).
py-two-side-program-comment = Lets the fragment shader’s gl_Color be the back colour on a triangle’s back side, as fixed-function GL chooses it; the shaders use it under glShadeModel(GL_FLAT).
# phonglab-py: the Python package
python-unknown-value = { $what }{ $value }: the values it takes are { $names }
python-wrong-length = { $field }: { $count ->
        [one] 1 number given
       *[other] { $count } numbers given
    }, { $expected } expected{ $hint }
python-hint-alpha = ; a colour is r, g, b, a: add its alpha, as [0.8, 0.2, 0.2, 1]
python-hint-w = ; a light's position is x, y, z, w: w = 1 for a light at a point, 0 for a light far away in that direction, as [0, 0, 90, 1]
python-hint-normal = ; a normal is a direction: x, y, z, or the worksheet's x, y, z, 0 (its w is 0)
python-hint-vertex = ; a vertex is x, y, z (its w is then 1) or x, y, z, w
python-either-3-or-4 = 3 or 4
python-no-such-light = there is no light { $light }: the scene has { $count ->
        [0] no lights
        [one] 1 light, numbered 0
       *[other] { $count } lights, numbered from 0
    }
python-not-real = { $what } = { $value }: not a number. Give real numbers: an int or a float, or a list or NumPy array of them (a text, True or False, None and complex numbers are not read as numbers; in Python write 25.6, not "25,6")
python-not-integer = { $what } = { $value }: not a whole number; give an int, such as 5
python-not-a-scene = { $what }: { $value } is not a phonglab.Scene; make one first: phonglab.Scene.load("scene.toml"), phonglab.Scene.worksheet(5) or phonglab.Scene.preset("phong-demo")
python-not-a-name = { $what } = { $value }: not a text; give a str, such as scene.name = "mview3's camera"
python-edit-fields = { $what } is not replaced whole: edit its fields one by one, as { $example }
python-load-notebook = { $path } is a notebook or a script, not a scene file: read the scene it sets up with phonglab.Scene.from_notebook(path)
python-no-field-guess = { $what } has no { $value }: did you mean { $guess }? Its names: { $names }
python-no-field = { $what } has no { $value }; its names: { $names }
python-lights-fixed = scene.lights has no { $value }: the lights are the scene's, edited here field by field (scene.lights[0].position = ...); a light is added or removed in a scene file, which Scene.load then reads
python-no-memory = not enough memory: { $bytes } bytes could not be had; light the vertices in smaller chunks
python-check-reassigned = Note: { $name } is assigned again in a cell run after the one that prints it, so the self-check reads the value { $name } holds now, not the one printed (phonglab check reads the printed one). Use another name there, or run the cells in order again.
python-overflow = { $step } is { $value } in { $precision }: the scene's numbers are past what { $precision } holds (float32: ±3.4e38), so the lighting overflows; nothing is returned (precision="f64" holds more)
python-render-no-memory = not enough memory to render a { $size } x { $size } picture: it needs about { $bytes }, twice that is asked for first, and it could not be had; choose a smaller size
python-not-finite-row = { $name }: row { $row } is { $value }: every number must be finite and within float32's range (±3.4e38)
python-wrong-shape = { $name }: an array of shape { $shape }, where (N, 3) is expected, the same N for the positions and the normals
nb-self-check = Self-check: with the Python package phonglab installed (it is not on PyPI yet: install the wheel file, `pip install phonglab-*.whl`, which phonglab's `scripts/wheel` builds or your teacher hands out), uncomment the cell below and run it after the others. It compares each value this notebook computed with the key, step by step, and names the first wrong step and its likely cause. Nothing here depends on it.
check-rules = rules assumed: { $rules }
check-inputs-differ = your typed inputs differ from the assignment's: { $names }
check-other-scene = { $count } of your typed inputs differ from the assignment's: is this the right scene (--scene)? No cause is named for work typed for another scene
check-step = { $step }: yours { $student }, the key's { $key }: { $verdict }
check-first-wrong = first wrong step: { $step } (yours { $student }, the key's { $key })
check-all-right = all right: every step printed is the key's
check-cause = likely cause: { $words } [{ $id }]. Evidence: for { $step }, you printed { $student }, and the key with this mistake gives { $value }
check-cause-formula = the formula with this mistake (a model of it, not your code): { $formula }
check-no-cause = no mistake in the catalogue reproduces everything you printed; look at the first wrong step
check-given-not-finite = not checked: a given is not a finite number ({ $givens })
check-printed-twice = printed more than once, with different values (each printing is checked): { $names }
check-input-rules = the rule set
check-given-not-followed = not checked: a given is changed in place, which the checker does not follow ({ $givens }): assign it whole in one line
# py58b: the notebook's self-check, the worked calculation's table
python-check-no-cells = phonglab.check(globals()) checks a Jupyter notebook: it reads the cells run so far from the notebook's In, and this Python has none. For a script, save what it prints and check that: python3 script.py > printed.txt, then phonglab check --printed printed.txt
python-check-run-first = nothing to check yet: none of the worksheet's cells has run in this kernel (after a restart, too). Run the other cells first (Run All), then this one
python-check-not-globals = phonglab.check reads the notebook's variables: pass globals(), with its brackets: phonglab.check(globals())
explain-column-step = step
explain-column-formula = formula
explain-column-value = value
explain-column-notes = notes
share-base-refused = the page a link opens must be an http:// or https:// address, without spaces, quotes or control characters: { $base }

## Files read and written (formats::files): shared by the command line, the window and the Python package

io-folder-missing = its folder { $folder } does not exist: make it first, or name a file in a folder that exists
io-not-found = it does not exist
io-permission-denied = permission denied
io-storage-full = the disk is full
io-open-elsewhere = another program has it open (close it there, then try again)
io-handle-lost = the system lost track of a file or folder phonglab held open: a folder it was working in was renamed or replaced by a link while it wrote (under Wine, by a program outside Wine)
io-link-in-the-way = a link is in the way (put there, or changed while phonglab wrote): phonglab never follows one here
io-is-a-directory = it is a folder
io-not-a-directory = a part of the path is not a folder
io-read-only = the file system is read-only
io-already-exists = it already exists
io-invalid-name = not a file name
write-error = cannot write { $path }: { $what }: { $reason }; { $kept }
write-step-write = write
write-step-close = close
write-step-sync = sync to the disk
write-step-create = create
write-step-rename = rename
write-step-name = name
write-step-create-folder = create the folder
set-folder-is-a-file = it is a file, not a folder: phonglab writes a set of files into a folder; give a folder, or the name of a new one
folder-link-dangling = it is a link whose target does not exist, and phonglab makes no folder through a link
write-step-create-file-in = create a file in
write-kept-file = the file there before (if any) is unchanged
write-kept-nothing = nothing was written
write-not-a-regular-file = not a regular file (a link, a folder, a device or a pipe): phonglab writes only a regular file or a new one
read-cannot = cannot read { $path }: { $reason }
read-not-a-file = { $path } is not a regular file
read-device-name = { $path } is a name Windows keeps for a device (CON, PRN, AUX, NUL, COM1…, LPT1…), not a file: phonglab reads no device; give the file's own name
read-too-large = { $path } is { $size }; phonglab reads { $what } of at most { $cap }
read-not-utf8 = { $path } is not UTF-8 text (byte { $byte })
read-link-refused = { $path } is a link: not read (a student’s work is read only from a file itself, never through a link)
file-kind-scenes = scene files
file-kind-code = notebooks and scripts
err-output-is-input = { $output } is { $what } { $input }, which this command reads (the same file): writing it would destroy what is read; choose another output
err-output-is-other-output = { $output } is the other output { $other } (the same file): one would be written over the other; choose two different files
err-name-windows-device = { $name } is a name Windows keeps for a device; choose another
err-name-windows-char = { $name } holds “{ $char }”, which Windows does not allow in a file name (a “:” writes a hidden stream of another file); choose a name without it
err-name-windows-quote = { $name } holds a “"”, which Windows does not allow in a file name. In cmd, a backslash just before a closing quote keeps the quote and joins what follows to the name: write a folder without its last backslash ("C:\Exercícios de CG", not "C:\Exercícios de CG\")
err-name-windows-end = Windows drops a dot or a space at the end of a name ({ $name } would be { $kept }, another file); choose a name without one
input-kind-input = the input
input-kind-scene = the scene
input-kind-mesh = the mesh
input-kind-code = the notebook or script
input-kind-cases = the case file
# fix57c
check-verdict-too-few-digits = too few digits to tell (printed to { $decimals ->
        [one] 1 decimal place
       *[other] { $decimals } decimal places
    }, which cannot tell the key from a mistake's value or from 0: print more, e.g. np.set_printoptions(precision=8))
check-too-few-digits = not checked whole: too few digits to tell the key from a mistake's value or from 0 ({ $names }; { $decimals ->
        [one] 1 decimal place
       *[other] { $decimals } decimal places
    } seen). Print more digits (np.set_printoptions(precision=8) at the top, or NumPy's default), run every cell again (Jupyter: Restart & Run All, in the Kernel menu), and check it again
check-stale-count = not checked whole: a cell's execution count is not a run's ([{ $count }]: Jupyter numbers the cells it runs 1, 2, 3, in order), so nothing says the outputs are from one run in order. Run every cell again (Jupyter: Restart & Run All, in the Kernel menu), save, and check it again
check-stale-not-run = not checked whole: a cell of code between those numbered [{ $above }] and [{ $below }] has no execution count (it was not run in that run, or its outputs were cleared), so the outputs below it are not from its code run in order. Run every cell again (Jupyter: Restart & Run All, in the Kernel menu), save, and check it again
