# phonglab's messages in English.

## app

language-menu-hover = Language, and how numbers are written (0,5 or 0.5)
leave-presenting = Leave (F5)
present = Present (F5)
present-hover = Large type; the controls in a drawer
controls-drawer = Controls drawer
controls-drawer-hover = The scene's controls, in a drawer
controls = Controls
calculation = Calculation
theme-hover = Both themes are high-contrast
theme-light = Light theme
theme-dark = Dark theme
reset-worksheet = Reset to worksheet
scene-menu = Scene
scene-menu-hover = The shipped scenes, and the worksheet's own
file-menu = File
view-menu = View
view-menu-hover = Panels, windows, the theme and the arithmetic
things-to-try = Things to try
things-to-try-hover = Experiments in one click: each sets up a scene, says what to look for and asks a question the calculation answers
things-to-try-band = Things to try: one click sets each up
things-to-try-intro = Click one to set up its scene (the current one is replaced; Ctrl+Z brings it back).
things-to-try-look = What to look for
things-to-try-question = The question
things-to-try-show = Show the calculation's answer
things-to-try-answer = Step { $step }: { $value }
things-to-try-no-step = The calculation has no step { $step } for this scene.
things-to-try-own = Your own experiments: .toml files in { $folder } (see assets/experiments/ for the form).
things-to-try-own-none = Your own experiments can be added in the desktop app.
experiment-no-text = it has no [text.en], [text.pt-PT] or [text.pt-BR]
experiment-no-scene = no scene named { $scene } (a shipped scene, or a .toml file beside the experiment)
experiment-no-control = no control is labelled by the message “{ $control }” (give a label’s id, such as light-z or material-shininess)
experiment-scene-refused = the scene { $scene } is not read: { $why }
experiment-scene-not-beside = an experiment names a shipped scene (such as worksheet-mview1) or a scene file beside it by its name alone (such as my-scene.toml), not a folder, a path or a link
experiment-scene-error = the scene { $scene } does not load: { $error }
experiment-changes-refused = its [changes] laid over the scene { $scene } do not give a scene: { $error }
experiment-folder-full = not read: the experiments folder is read for at most { $most } in all, its scenes included
experiment-too-many = not read: at most { $most } experiments are read from the folder
file-kind-experiments = experiment files
panels-heading = Panels and windows
arithmetic-heading = Arithmetic
file-menu-hover = The scene file, export, undo and redo
redbook-teapots = Red Book teapots
compare = Compare
compare-hover = Pin the scene as A, change anything, and see A and B side by side
director = Director's view
director-hover = The scene from outside: the eye and its frustum, the lights with their rings and cones, the worked vertex with N, L, V and H, in object, world or eye space
director-space = Space
space-object = Object
space-world = World
space-eye = Eye
director-eye = eye
director-vertex = vertex
director-light = light { $n }
director-legend = at the vertex, one length each (their true directions in this space); blue square: the near plane (the viewport); green square: the surface at the vertex. Drag a light or the eye to move it; drag elsewhere to turn; scroll to zoom.
director-naive-normal = Dotted, in light blue: M n, the normal moved as a point would be, { $degrees }° off the true normal (M^-1)^T n, which stays perpendicular to the surface.
director-rules-naive = This scene's rules (the worksheet's) light the vertex with M n; OpenGL's use (M^-1)^T n.
director-ring = Light { $n }: 1/at, the attenuation factor, falls to { $percent } % at distance { $distance } (a ring).
wrong-cause-normals-by-m = Normals transformed by M instead of its inverse transpose
wrong-why-normals-by-m = Under a scale that differs along the axes, M moves the surface one way and its normals another: M n is no longer perpendicular to the surface, and (M^-1)^T n is.
wrong-cause-normal-not-normalised = The normal not normalised (GL_NORMALIZE off under a scaled modelview)
wrong-why-normal-not-normalised = A modelview that scales by 0.5 makes the transformed normal 2 long, and nothing brings it back to 1: n · L doubles, and with it the diffuse term; near the highlight n · H passes 1, and the power s_rm blows the specular term up into a white patch.
wrong-cause-reflection-for-halfway = The reflection vector (R · V) used where the halfway vector (n · H) belongs
wrong-why-reflection-for-halfway = The angle between R and V is about twice the angle between n and H, so R · V falls off faster: at the same exponent the highlight is smaller.
wrong-cause-gouraud-misses-highlight = Gouraud shading: lit only at the vertices, so a highlight between them is lost
wrong-why-gouraud-misses-highlight = The highlight falls between the coarse sphere’s vertices: none of them sees it, and interpolating their colours cannot make it.
wrong-cause-specular-facing-away = Specular light on faces turned away from the light (no f_i)
wrong-why-specular-facing-away = OpenGL multiplies the specular term by f_i, 1 only where n · L > 0. Without it n · H can still be positive on the dark side: a highlight glows where no light reaches.
wrong-cause-attenuation-object-space = Attenuation computed with the distance in object space
wrong-why-attenuation-object-space = The model scales by 0.25, so distances in object space are 4 times those in eye space: at = k0 + k1 d + k2 d² grows, every term is divided by more, and the light fades too soon. OpenGL measures d in eye space.
wrong-cause-light-before-view = The light’s position given before the view transform
wrong-why-light-before-view = glLightfv(GL_POSITION) multiplies the position by the modelview current at that moment. Given before gluLookAt, it is taken in eye coordinates: the light rides with the camera instead of staying in the world.
wrong-probe-line = bytes { $rgba }, n · L = { $ndotl }, { $cosine } = { $ndoth }, 1/at = { $att }, diffuse { $diffuse }, specular { $specular }
wrong-key-cause = Cause: { $cause }.
wrong-key-formulas = Right: { $right }. The mistake: { $wrong }.
wrong-formula-gouraud-right = lit per fragment (Phong)
wrong-formula-gouraud-wrong = lit per vertex, interpolated (Gouraud)
wrong-formula-facing-away-right = f_i = 1 only where n · L > 0
wrong-formula-facing-away-wrong = f_i = 1 everywhere
wrong-formula-attenuation-right = d = |P_pli - P| in eye space
wrong-formula-attenuation-wrong = d measured in object space
wrong-key-pixel = The probe at pixel ({ $x }, { $y }), where the two pictures differ most ({ $count } pixels differ):
wrong-key-right = drawn right: { $line }
wrong-key-wrong = with the mistake: { $line }
wrong-key-term = The term that changes most at this pixel: { $term } ({ $name }), its luminance from { $right } drawn right to { $wrong } with the mistake.
wrong-key-normals = The fragment’s normal turns by { $degrees }°.
wrong-title = What is wrong with this picture?
wrong-intro = Each sheet shows a sphere drawn right and drawn with one mistake. Pick the mistake; the key explains it with the pixel probe’s numbers.
wrong-sheet-title = What is wrong with this picture? ({ $number })
wrong-drawn-right = Drawn right
wrong-drawn-wrong = Drawn with one mistake
wrong-question = Which one mistake makes the right-hand picture? Tick it, and say what in the picture shows it.
wrong-written = { $count } pictures with one mistake each, with their keys, in { $out }
wrong-quiz-hover = A sphere drawn right and drawn with one mistake: pick the mistake
wrong-check = Check
wrong-right-answer = Right.
wrong-wrong-answer = Not that one. The key:
wrong-back = Back to the calculation
share-too-long = the link is { $length } characters long; phonglab reads at most { $most }
share-version = the link is of version “{ $found }”; this phonglab reads v{ $version }
share-damaged = the link is damaged ({ $what }): it was cut or changed
share-choice = the link asks for something this phonglab does not know: “{ $line }”
share-summary = a link of { $length } characters: the scene is in the link itself
share-window = Share this scene
share-menu = Share link…
share-menu-hover = The scene as a link and a QR code, for the class to open in a browser (nothing is stored on a server: the scene is in the link)
share-page = Page the link opens
share-page-hover = Where the browser build is published (empty: this page in a browser, else the project's site)
share-in-language = Open in { $lang }
share-presenting = Open presenting to a class
share-channel = Open showing { $term }
share-length = { $length } characters: the scene is in the link itself
share-copy = Copy link
share-copy-hover = Puts the link on the clipboard, to paste in the class's chat or page
share-copied = Link copied ({ $length } characters): paste it for the class, or let them scan the code.
share-qr = QR code of the link
share-qr-too-long = The link is too long for a QR code; copy it instead.
err-share-lang = unknown language { $value }: en, pt-PT or pt-BR
share-opened = the shared link ({ $name })
share-not-opened = The shared link was not opened: { $why }. This is the scene you had.
mesh-missing-kept = The mesh { $path } is missing or cannot be read ({ $error }); the scene is kept and shown on the sphere. Open the mesh again to show it.
share-needs-mesh = The link's scene shows the mesh { $name }, which a link does not carry: open or drop { $name } to see it (the sphere stands in until then).
mesh-not-kept = (Not kept for a reload of the page: { $why }; open it again after one.)
mesh-too-large-to-keep = packed, it is { $packed } characters, and the page keeps at most { $most }
mesh-not-restored = The mesh { $name } this page kept could not be read back ({ $why }): open it again.
quiz = Quiz
quiz-hover = Every value of the calculation behind a field: type them step by step
shader = Shader
shader-hover = The GLSL or WGSL program this scene compiles to: only the stages it needs
precision = Precision:
f32-hover = Evaluate in single precision, as OpenGL does
f64-hover = Evaluate in double precision
cost-of-accuracy = Cost of accuracy
cost-hover = What each shading, tessellation and approximation costs in time and in error
help-button = Help (F1)
undo-what = Undo: { $what } (Ctrl+Z)
redo-what = Redo: { $what } (Ctrl+Shift+Z, Ctrl+Y)
undo-button = ⟲ Undo
redo-button = ⟳ Redo
nothing-to-undo = Nothing to undo
nothing-to-redo = Nothing to redo
could-not-evaluate = Could not evaluate the scene ({ $error }); back to the worksheet.
keyboard-shortcuts = Keyboard shortcuts
vectors-at-vertex = Vectors at the vertex
reflection-lobe = Reflection lobe
session-not-saved = The session could not be saved: { $error }.
no-session-folder = There is no folder to keep the session in (HOME is not set): this window will not save its session.

## names

doc-worksheet = the worksheet, mview{ $k }
doc-worksheet-preset = Worksheet, mview{ $k }

## presets

preset-group-worksheet = The worksheet
preset-group-phong-demo = The Phong demo
preset-group-more = More scenes
preset-worksheet = Worksheet, { $modelview }
preset-phong-demo = Phong demo
preset-spotlight = Spotlight
preset-three-lights = Three lights
preset-of-set-color = ofSetColor under lighting
preset-gouraud-misses-the-highlight = Why Gouraud misses the highlight
doc-phong-demo = the Phong demo
doc-spotlight = a spotlight
doc-three-lights = three coloured lights and a headlight
doc-of-set-color = openFrameworks' ofSetColor under lighting
doc-gouraud-misses-the-highlight = why Gouraud misses the highlight
doc-redbook-teapot = Red Book teapots: { $material }

## controls

controls-rules = Rules
controls-lights = Lights
controls-material = Material
controls-light-model = Light model
controls-vertex = Vertex
controls-camera = Camera (modelview)
rule-set = Rule set
specular-model = Specular model
specular-blinn-phong-normalised = Normalised Blinn-Phong (n.H)·(ns+8)/8π
rules-opengl-summary = Emission + scene ambient + every light's ambient, diffuse and specular (OpenGL 2.1, 2.14.1).
rules-worksheet-summary = The worksheet: no scene ambient, no emission; diffuse 0 past 90 degrees, specular 0 past 90 degrees.
rules-demo-summary = The Phong demo's shader: no scene ambient, no emission, pow(max(R.V, 0), e) with no other gate.
ruleset-worksheet = Worksheet
ruleset-demo = Phong demo
pow-exact = exact pow
placement-eye = the eye (moves with the camera)
placement-world = the world
placement-object = the object (turns with it)
placement-matrix = a typed matrix
add-light = Add light
remove-light = Remove light
lights-count =
    { $count ->
    [one] { $count } light
    *[other] { $count } lights
    }
lights-of-max = { $count } of { $max }
light-tab = Light { $index }
no-lights = No lights: only emission and the scene ambient remain.
directional = Directional (w = 0)
light-x = Light x
light-y = Light y
light-z = Light z
light-fixed-to = Light fixed to
light-ambient = Light ambient
light-diffuse = Light diffuse
light-specular = Light specular
attenuation-constant = Constant attenuation
attenuation-linear = Linear attenuation
attenuation-quadratic = Quadratic attenuation
attenuation-positional-only = Attenuation applies to positional lights only.
spotlight = Spotlight
spotlight-hover = A new spotlight aims at the object in the view
spot-direction = Spot direction
spot-cutoff = Spot cutoff
spot-exponent = Spot exponent
material-custom = custom
material-preset = Material preset
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
back-preset = Back preset
back-ambient = Back ambient
back-diffuse = Back diffuse
back-specular = Back specular
back-emission = Back emission
back-shininess = Back shininess
separate-back-material = Separate back material
color-material = Colour material (GL_COLOR_MATERIAL)
color-material-hover = The material colours it tracks follow the current colour (glColor), as openFrameworks' ofSetColor does under ofEnableLighting
color-material-mode = Tracks
color-material-face = Faces
color-material-color = Current colour (glColor)
color-material-tracked = GL_COLOR_MATERIAL makes this the current colour: what is set here returns when it is off
scene-ambient = Scene ambient
local-viewer = Local viewer
two-sided = Two-sided lighting
separate-specular = Separate specular colour
normals-as-is = as transformed
normals = Normals
vertex = Vertex
normal = Normal
normalise-normal = Normalise the normal
camera = Camera
camera-kind-worksheet = Worksheet modelview
camera-kind-of = openFrameworks camera
camera-kind-matrix = Typed 4x4
camera-eye = Eye
camera-centre = Centre
camera-up = Up
window-width = Window width
window-height = Window height
of-eye-distance = Eye distance (H/2)/tan(30 deg) = { $distance }
object-placement = Object placement (world from object)
object-matrix = Object
matrix-column = column { $column }
matrix-row = { $name } row { $row }
matrix-cell = { $name } row { $row } column { $column }
mview1-what = the openFrameworks camera, translate z by −665.108
mview2-what = a rotation about x, as printed (one entry with a digit less, −0.85749)
mview34-what = built from 15/17 and 8/17, as the worksheet prints it
mview5-what = a 3-4-5 rotation about x and translate z by −960

## result

unclamped = unclamped
unclamped-hover = The primary colour as the equation gives it.
clamped = clamped
clamped-hover = Primary + secondary rgb, clamped to [0, 1]: what a fragment gets.
dark-vertex = a dark vertex: { $percent } % as bright as white
dark-vertex-angle = a dark vertex: { $percent } % as bright as white; the light meets it at { $angle }°
dark-vertex-short = dark vertex
large-value-hover = The colour as drawn (clamped to [0, 1]), r g b to two decimals
secondary = secondary
secondary-hover = The secondary (specular) colour.
vertex-colour = Vertex colour
front-face = Front face
back-face = Back face
colour-hidden = Hidden while the quiz is open: it is the quiz's last answer, I.
colour-hidden-teacher = The teacher can show it with "Show the answers" in the quiz.
refused-kept = Refused: { $error }. The scene keeps its last valid value.
history-reset = reset to the worksheet
reset-done = Reset to the worksheet (mview5).
history-open = open { $what }
loaded = Opened “{ $what }”
undid = Undid: { $what }.
redid = Redid: { $what }.
history-no-change = no change
history-and-more = { $field } and { $count } more
history-light-added = light { $index } added
history-light-removed = light { $index } removed
history-none = (none)
history-on = on
history-off = off
# A changed field of the scene, as the undo history names it. $field is the scene file's
# path with dots as dashes and a light's number taken out (light-position of light $index).
history-field = { $field ->
    [name] scene name
    [rules] { rule-set }
    [specular] { specular-model }
    [normals] { normals }
    [light_model-ambient] { scene-ambient }
    [light_model-local_viewer] { local-viewer }
    [light_model-two_sided] { two-sided }
    [light_model-separate_specular] { separate-specular }
    [camera] { camera }
    [object_matrix] { object-placement }
    [material-preset] material
    [material-ambient] { material-ambient }
    [material-diffuse] { material-diffuse }
    [material-specular] { material-specular }
    [material-emission] { material-emission }
    [material-shininess] { material-shininess }
    [back_material] { separate-back-material }
    [color_material] { color-material }
    [light-position] light { $index } position
    [light-ambient] light { $index } ambient
    [light-diffuse] light { $index } diffuse
    [light-specular] light { $index } specular
    [light-spot_direction] light { $index } spot direction
    [light-spot_cutoff] light { $index } spot cutoff
    [light-spot_exponent] light { $index } spot exponent
    [light-attenuation] light { $index } attenuation factors (k0, k1, k2)
    [light-placement] light { $index } fixed to
    [vertex-position] { quantity-vertex-position }
    [vertex-normal] { quantity-vertex-normal }
    [view-object] object
    [view-obj] { mesh-file }
    [view-shading] shading
    [view-sphere_slices] { sphere-slices }
    [view-sphere_stacks] { sphere-stacks }
    [view-teapot_grid] { teapot-grid }
    [view-cylinder_slices] { cylinder-slices }
    [view-cylinder_stacks] { cylinder-stacks }
    [view-cylinder_caps] cylinder caps
    [view-cylinder_centered] cylinder centred
    [view-demo_normals] { demo-normals }
    [view-auto_rotate] { auto-rotate }
    [view-spin_degrees] spin
    [view-framing] framing
    [view-lighting_space] lighting space
    [view-flat_normal] { flat-derivatives }
    [view-phong_renormalize] { phong-renormalises }
    [view-background] background
    [view-camera] view camera
   *[other] the scene
}
not-whole = { $text } is not a whole number
outside-range = { $text } is outside { $min } to { $max }
numbers-type-one = { $count } numbers: type one
numbers-type-row = { $count } numbers: type one, or all { $fields } of the row
refused-esc = { $why } (Esc: back to { $value })
typed-empty = no value
typed-not-a-number = "{ $text }" is not a number
typed-not-finite = { $text } is not a finite number
typed-too-large = { $text } is beyond single precision's range (±3.4e38)
typed-too-small = { $text } is too small for single precision: it would be 0

## help

help-help = show or hide this help
help-present = present: large type, the controls in a drawer (F5 again to leave)
help-walk-steps = walk through the calculation's steps, one at a time (when no field has the keyboard)
help-zoom = zoom the whole window in, out, back to 100 %
help-things-to-try = Things to try (top bar): experiments in one click, each with a question the calculation answers.
help-local-viewer = toggle the local viewer
help-next-material = next classic material
help-previous-material = previous classic material
help-next-modelview = next worksheet modelview (mview1..5)
help-specular-model = next specular model (Blinn-Phong, Phong, normalised Blinn-Phong)
help-next-rules = next rule set (OpenGL, worksheet, Phong demo)
help-next-normals = next normal mode (as is, normalize, rescale)
help-two-sided = two-sided lighting on/off
help-precision = f32 / f64 evaluation
help-reset = reset to the worksheet
help-open = open the scene file at the typed path
help-save = save the scene to the typed path
help-quit = quit (the session is saved)
help-undo = undo the last change of the scene
help-redo = redo
help-sphere = shaded view: sphere (as the demo)
help-teapot = shaded view: teapot
help-cylinder = shaded view: cylinder
help-gouraud = Gouraud shading (as the demo)
help-phong = Phong shading
help-flat = Flat shading
help-auto-rotate = auto-rotate the shaded view
help-drop = Drop a scene file (.toml) on the window to open it.
help-drag = Drag the vector plot or the shaded view to orbit it; scroll the shaded view to zoom; click its surface to explain that vertex.
help-numbers = A number field takes a decimal point or comma, and reads what was typed when it is left (Enter, Tab, a click elsewhere); a refused value stays in red with its reason until it is corrected or Esc puts the value back.
help-undo-keys = Ctrl+Z undoes any change of the scene. Keys without Ctrl do nothing while a text field has the keyboard, nor in the quiz.
help-demo-title = The Phong demo preset: the demo's choices and OpenGL's
help-demo-space = The demo's: lighting in object space, light and eye at (-4, 0, -8), so the light turns with the object. OpenGL's: lighting in eye space after the modelview (switch: light fixed in the world).
help-demo-normals = The demo's: every normal is normalize(position). OpenGL's: the surface's normals (switch: the surface's true normals).
help-demo-specular = The demo's: R = 2 max(N.L, 0) N - L and pow(max(V.R, 0), 100), times the object's red, so the highlight is red. OpenGL's: Blinn-Phong's n.H and the light's specular colour times the material's (switch: highlight in the light's colour).
help-demo-pipeline = The demo's: no projection (the picture is clip space), Phong without renormalising, Flat from dFdx/dFdy per fragment, colours interpolated unclamped. Under Pipeline, the shaded view offers OpenGL's choices.

## quiz

quiz-input-yours = your { $name } = { $value }
quiz-input-key = the key's { $name } (not answered yet)
quiz-the-givens = the givens
quiz-right = ✔ right
quiz-right-given = ✔ right, given your { $yours }
quiz-close-key = ≈ close: { $percent } % from the key; give { $digits } significant digits
quiz-close-yours = ≈ close: { $percent } % from what your earlier answers give; give { $digits } significant digits
quiz-wrong = ✖ wrong: { $formula }, with { $inputs }
quiz-level = Level
quiz-levels = 1 directional, 2 positional with attenuation, 3 spotlights, 4 two-sided with several lights
quiz-this-scene = Quiz this scene
quiz-this-scene-hover = Start over on the scene shown, every value hidden
quiz-new-exercise = New exercise
quiz-new-exercise-hover = A new scene of this level, screened as phonglab exercise screens
quiz-reveal-all = Show all the answers
quiz-reveal-all-hover = Show the key's value under every step: none then counts as right
quiz-clear = Clear answers
quiz-clear-hover = Start this quiz again with no answers
quiz-show-answers = Show the answers (teacher)
quiz-show-answers-hover = The vertex colour, the plot's angles and every step's key
quiz-nothing-open = Open an exercise (phonglab exercise writes them) or any scene, then press "Quiz this scene", or press New exercise.
quiz-instructions = { $scene }: type each step's value and press Enter. Right: within { $percent } % of the value (or { $absolute } near 0). A point or a comma; a vector as 0,5; 0,3; 0,1.
quiz-score = Score: { $right } of { $all } ({ $answered ->
    [one] 1 answered
   *[other] { $answered } answered
}{ $shown ->
    [0] {""}
    [one] , 1 answer shown
   *[other] , { $shown } answers shown
})
quiz-your-value = your value
quiz-reveal = Show the answer
quiz-reveal-hover = Show the key's value for this step: it then no longer counts as right
quiz-not-numbers = does not read as numbers: { $error }
quiz-key = key: { $name } = { $value }

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
gate-lit-side = f = 1 if cosTheta > 0
gate-positive = only where cos > 0
gate-none = no gate
formula-specular = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns   ({ $gate }; f = { $f }; OpenGL: s_cl · s_cm · max(n · h, 0)^s_rm)
formula-specular-normalised = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns · (ns + 8)/(8π)   ({ $gate }; f = { $f }; energy-conserving Blinn-Phong: the narrower the highlight, the brighter, the light it reflects the same; OpenGL has no such factor)
formula-at = at = atC + atLin · d + atQuad · d²   (OpenGL: the terms are divided by k0 + k1 d + k2 d²)
formula-at-directional = at = 1   (directional)
formula-spot = spot = max(-L . s, 0)^e if -L . s >= cos(cutoff) = { $cutoff }, else 0;  -L . s = { $angle }
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

## calculation

plan-heading = Specialised plan: { $computed } effects computed, { $skipped } skipped
plan-light = light { $index }:{" "}
plan-computed = computed  { $what }
plan-skipped = skipped   { $what }
plan-program = The program, { $stages } stages per chunk of vertices:
worked-calculation = Worked calculation
copy-markdown = Copy as Markdown
copy-markdown-hover = Copies every step as a Markdown table.
side = Side:
not-applicable = n/a
skipped-by-specialised = skipped by the specialised evaluator: { $why }
plot-view = View:
plot-legend-halfway = halfway
plot-view-hover = Look at the { $plane } plane

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
pipeline = Pipeline: OpenGL's or the demo's
picture = Picture
phong-renormalises = Phong renormalises N
phong-renormalises-hover = OpenGL shaders normalise the interpolated normal; the demo's does not
flat-derivatives = Flat from dFdx/dFdy
flat-derivatives-hover = The demo's Flat: each fragment lit with cross(dFdy(p), dFdx(p)); otherwise one colour per face
correct-the-demo = Correct the demo:
why-demo-differs = Why the demo differs
why-demo-differs-intro = Each switch on corrects the demo in a second picture, on the right of its own.
sphere-slices = Sphere slices
sphere-stacks = Sphere stacks
teapot-grid = Teapot grid
cylinder-slices = Cylinder slices
cylinder-stacks = Cylinder stacks
caps = Caps
mesh-triangles = { $count } triangles: { $notes }
key-hint = key { $key }
mesh-tip = { $path } (open another under View options, or drop an .obj file)
close-mesh = Close your mesh
close-mesh-hover = Close your mesh: the top bar offers it no more (it stays in its file; changing scene keeps it until then)
auto-rotate = Auto-rotate
auto-rotate-hover = 0.5 degrees a frame, as the demo (key A)
demo-normals = Demo's normals
demo-normals-hover = normalize(position), as the demo: wrong for the teapot and the cylinder
heat-map = Error heat map
heat-map-hover = Beside the view: how far each pixel is from per-pixel Phong in f64 on a very fine mesh
view-options = View options
view-options-hover = The renderer, the mesh's resolution, the pipeline's choices, a mesh file
mesh-file = Mesh file (.obj):
show-mesh = Show mesh
show-mesh-hover = Shade this OBJ file in the view (Enter in the field)
shaded-cannot-render = The shaded view cannot render this scene
corrected-cannot-render = The corrected view cannot render
the-demos-own = {" "}(the demo's own)
picture-hover = Drag to orbit, scroll to zoom, click the surface to make that vertex the worked calculation's
corrected = Corrected: { $fixes }
corrected-short = Corrected ({ $count } of { $all })
picked-vertex = Vertex { $index } of the { $object }: the worked calculation now uses it, as the shaded view lights it.
light-behind = light { $index } (behind the camera)
light-name = light { $index }
light-drag = Light { $index }: drag to move it
arrows-faded = Faded, open head: the vector points away from you, or into the surface.
renderer = Renderer
renderer-hover = The CPU renderer is the reference; the GPU runs the scene's generated WGSL (Shader window)
renderer-auto = Automatic (GPU if a real one)
renderer-cpu = CPU (the reference)
renderer-gpu = GPU (even a software one)
drawn-gpu = Drawn on the GPU ({ $adapter }) by the scene's generated WGSL.
drawn-cpu = Drawn by the CPU renderer: { $why }.
gpu-none = no GPU here
caption-gpu = on the GPU ({ $adapter })
caption-cpu = { $ms } ms per frame on the CPU
caption-cpu-relit = lit again, nothing drawn moved: { $ms } ms per frame on the CPU
caption-cpu-coarse = a copy of { $triangles } of the { $all } triangles while the camera turns: { $ms } ms per frame on the CPU
caption-cpu-coarse-spin = a copy of { $triangles } of the { $all } triangles while the object spins: { $ms } ms per frame on the CPU
cpu-flat = Flat shading is drawn by the CPU renderer (the generator writes Gouraud and Phong)
cpu-approximate-pow = an approximate power function is studied on the CPU renderer (the GPU's pow is its own)
cpu-no-adapter = no wgpu adapter here (headless, or another backend)
cpu-chosen = the CPU renderer is chosen under View options
cpu-software-adapter = the adapter ({ $adapter }) is a software one, no faster than the CPU renderer

## files

not-opened-worksheet = Not opened: { $why }. Showing the worksheet instead.
not-opened = Not opened: { $why }. The current scene is unchanged.
mesh-summary = { $triangles } triangles, { $vertices } vertices; { $notes }
opened-mesh = Opened the mesh { $path }: { $what }.
not-text = { $path } is not a text file
saved = Saved { $path }.
not-saved = Not saved: { $error }.
scene-file = Scene file:
scene-file-hint = path/to/scene.toml
open = Open
open-hover = Open the scene file at this path (Ctrl+O)
save = Save
save-hover = Save the scene to this path (Ctrl+S)
open-dialog = Open…
open-dialog-hover = Choose a scene file in the system's file dialog
dialog-no-session-bus = The system's file dialog cannot open here (no desktop session bus for its portal): choose the file in phonglab's own chooser.
dialog-did-not-open = The system's file dialog did not open (no desktop portal answered): choose the file in phonglab's own chooser.
dialog-in-app = Choose the file here.
chooser-title = Choose a file
chooser-folder = Folder:
chooser-up = Up
chooser-name = File name:
chooser-cancel = Cancel
chooser-empty = (no folders or files of this kind here)
save-as = Save as…
save-as-hover = Choose where to save in the system's file dialog
drop-to-open = Drop a scene file (.toml) or a mesh (.obj) to open it
cannot-read = cannot read { $path }: { $error }
dropped-several = {" "}({ $count } files were dropped; only the first is opened.)
type-path-first = Type the scene file's path first.

## browser

browser-no-storage = this browser keeps no local storage for the page
browser-storage-refused = the browser refused to keep the session ({ $error })
browser-download-failed = the browser could not offer the download ({ $error })
open-browser-hover = Choose a scene file (.toml), a mesh (.obj) or a worksheet notebook or script (.ipynb, .py) on this computer
save-download-hover = Download the scene as a file (.toml)
downloaded = Offered { $name } as a download.

## export

export = Export
export-png = Shaded view as PNG ({ $size }×{ $size })
export-png-hover = The shaded view drawn by the CPU renderer, as phonglab render draws it
export-exercises = Exercise sheets
export-seed = Seed
export-count = Exercises
export-level = Level
export-levels = 1 directional, 2 positional with attenuation, 3 spotlights, 4 two-sided with several lights
export-exercises-save = Save the sheets (.zip)
export-exercises-hover = The sheets and their keys, as Markdown, scene files and the two PDFs (sheets.pdf to hand out, keys.pdf for the teacher), in this language
exported = Saved { $what }: { $at }
not-exported = { $what } was not saved: { $error }

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

    The vector (obsPos - vertexPos) is computed differently for `glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, true/false)`: when **true**, obs = [0 0 0 1]; when **false**, only the z component is kept: obs = vertexPos * [1 1 0 1], and vov always comes out as [0 0 1 0].

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
nb-glcolor-comment = # the colour as drawn: clamped to [0, 1], alpha from the material's diffuse
nb-back = The back side (two-sided lighting): the same terms with the normal reversed (-vertexNormal) and the back material; the names end in Back.
nb-no-spot-comment = # not a spotlight (spotCutoff 180)
err-export-folder = openframeworks writes three files: give a folder with -o (they go into its src/)
export-written = written: { $path }
bench-mesh-written = mesh written: { $path } ({ $triangles } triangles, { $vertices } vertices)
bench-coarse-made = { $object }: the coarse copy has { $triangles } of { $all } triangles, made in { $ms } ms
import-written = scene written: { $path } ({ $lights })
import-unreadable = { $place }: cannot read `{ $line }`: { $reason }; ignored
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
import-limit-total = brings the names assigned so far past what phonglab reads: it { $limit }
bytes-described = { $bytes } bytes ({ $mib } MiB)
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
obj-over-budget = { $triangles } triangles take { $bytes } to read, more than the memory budget of { $budget } (--memory-budget raises it)
budget-over = { $what } needs about { $needed }, more than the memory budget of { $budget } ({ $from }); --memory-budget SIZE raises it (e.g. --memory-budget 16G)
budget-from-option = as --memory-budget asks
budget-from-system = half of the memory available
budget-size-refused = { $value }: write a size such as 512M, 8G or 1.5G
budget-what-render = a { $width } x { $height } picture of { $count ->
        [one] one triangle
       *[other] { $triangles } triangles
    }
budget-what-window = the window at { $width } x { $height } pixels
budget-what-cost = the study of { $count ->
    [one] one object
   *[other] { $count } objects
} at { $size } x { $size } pixels
budget-what-eval = lighting { $count ->
    [one] one case of { $largest }
   *[other] { $count } cases, one at a time, the largest { $largest }
} of JSON
file-kind-code = notebooks and scripts
cli-export = Write a scene as the student's own code: the worksheet's notebook, a PyOpenGL program, an openFrameworks app, or the GLSL
cli-import = Read a worksheet-style notebook (.ipynb) or Python script (.py) into a scene file
cli-arg-export-scene = A scene file (TOML); default: the worksheet's scene
cli-arg-export-to = What to write
cli-arg-export-output = Where: a file (a folder for openframeworks: the files go into its src/); without it the text goes to the standard output
cli-arg-import-file = A worksheet-style notebook (.ipynb) or Python script (.py)
cli-arg-import-output = The scene file to write (TOML)
cli-value-notebook = the worksheet's Jupyter notebook (.ipynb), with this scene's values
cli-value-pyopengl = a PyOpenGL + GLUT program in the Phong demo's style (.py)
cli-value-openframeworks = ofApp.h, ofApp.cpp and main.cpp for openFrameworks 0.12 (a folder)
cli-value-glsl = the GLSL that `phonglab shader` prints
export-flat-unsupported = the PyOpenGL program draws with the scene's generated shaders, which are Gouraud or Phong: choose one of them for the shaded view, not Flat
export-template-broken = the program template { $template } is filled wrongly ({ $problem }): this is a fault of phonglab's; please report it
py-title = { $scene }: the shaded view as phonglab draws it ({ $shading } shading), written by phonglab.
py-usage = Run: python3 phong_scene.py (a window; needs PyOpenGL, GLUT and NumPy). With --png FILE it draws one 512x512 frame (--size N: NxN), saves it to FILE and exits. The lighting state is set the fixed-function way (glLightfv, glMaterialfv, glLightModel*); the shaders are the scene's own (phonglab shader) and read that state back from GL.
py-rules-comment = the equation the shaders compute: "worksheet", "opengl" or "phong-demo" (the normal matrix and the scene's ambient follow it)
py-shaders-comment = The scene's shaders, as `phonglab shader` prints them, in a compatibility-profile context: a_position and a_normal are GL's own gl_Vertex and gl_Normal, which gluSphere, glutSolidTeapot and gluCylinder send.
py-uniforms-comment = The shaders' uniforms (name, type); set_uniforms() gives each its value from GL's state.
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
py-reader-doc = The value of the shaders' uniform u_NAME, read from GL's state (glGetLightfv, glGetMaterialfv, the matrices).
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
of-shader-comment = phonglab's generated shader (phonglab shader), for what fixed-function GL cannot compute: GL's own vertex, normal and matrices, the other uniforms set in draw()
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
export-code = Your own code
export-copy = Copy
export-copy-hover = Copy it to the clipboard (the notebook as one script, the openFrameworks files one after the other)
export-save = Save…
export-save-hover = Save it as a file (openFrameworks: a zip of the project's src/)
export-copied = Copied: { $what }
export-nothing = nothing to write
export-import-hint = To go the other way, open or drop a worksheet notebook (.ipynb) or script (.py): its values become the scene.
imported = Opened { $path } as a scene (the worksheet's rules unless it says otherwise).{ $notices }
py-normal-matrix-comment = OpenGL: the inverse transpose of the modelview's 3x3; the worksheet: the 3x3 itself.

## plots

plot-drag = Drag to orbit (yaw { $yaw }°, pitch { $pitch }°)
lobe-no-light = No light with a defined L at this vertex: nothing to plot.
lobe-axis = φ, degrees from N
lobe-luminance = { $name } = { $value } (the luminance of { $colour })
lobe-caption = Light { $light }: θ = { $theta }°, n = { $n }, { $kd }, { $ks }; the vertex's V at φ = { $phi }°
lobe-diffuse = diffuse kd cos θ
lobe-normalised = Blinn-Phong × (n+8)/8π
lobe-vertex-v = the vertex's V

## compare

compare-same = A and B are the same scene: change anything, and B follows
compare-one = B: { $setting } { $b }; A: { $a }
compare-several = A and B differ in { $names }
compare-many = A and B differ in { $count } settings
compare-view = { $which }'s shaded view, { $ms } ms
compare-cannot-render = { $which }'s view cannot render: { $error }
compare-pin-again = Pin the current scene as A again
compare-pin = Pin the current scene as A
compare-pinned = Pinned as A: now change anything, and B follows.
compare-close = Close compare
compare-difference = Difference |A − B|
compare-difference-hover = A third picture: how much A's and B's pixels differ, amplified
compare-difference-view = |A − B| × { $gain }
compare-difference-legend = Each channel's difference, times { $gain }: a channel is at full strength from { $full }/255 on (white where all three are, black where A and B agree). { $percent } % of the object's pixels differ by more than { $visible }/255; the largest difference is { $largest }/255.
compare-step-1 = 1. Pin the current scene as A (the button above).
compare-step-2 = 2. Change anything: the shading, f32 or f64, the material, a light.
compare-step-3 = 3. A and B show side by side, with the steps that differ first.
compare-a-fails = A cannot be evaluated: { $error }
compare-differing = { $differing } of { $all } steps differ: they come first, highlighted.
compare-none-differ = Nothing differs: A and B give the same value at each of the { $all } steps.
copy = Copy
copy-program-hover = Copy the program to the clipboard
shader-stages-phong = Phong (per fragment) shading: only the stages this scene needs
shader-stages-vertex = per vertex shading: only the stages this scene needs
shader-last-change = The last change added { $added } lines (highlighted) and removed { $removed }.
shader-removed = Removed by the last change:
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
session-other-window = Another phonglab window is open on this session ({ $dir }): this window shows its last saved scene but will not save its session. Use Save to keep your work in a file.
session-folder-unusable = The session folder { $dir } cannot be used ({ $error }): this window will not save its session.
session-file-is-folder = The session file { $path } is a folder, so the last session cannot be read and this window will not save its session. Remove or rename that folder.
session-unreadable-kept = The saved session could not be read ({ $why }); starting on the worksheet. The file is kept as { $kept }.
session-unreadable-not-kept = The saved session { $path } could not be read ({ $why }) nor set aside ({ $error }); it is left as it is, never written over: starting on the worksheet, and this window keeps its session in { $instead }.
session-unreadable = The saved session could not be read ({ $why }).
session-not-a-file = it is not a regular file: a pipe, a device or a socket
session-too-large = it is { $size }, and a session is at most { $cap }
session-scene-kept = The scene is kept in { $path }.
session-scene-not-kept = It could not be kept ({ $error }).
session-no-folder = There is no storage folder to keep it in.
session-scene-not-restored = The last session's scene could not be restored ({ $error }); starting on the worksheet. { $kept }

## sheets

exercise-modelview = rotate { $degrees } degrees about { $axis }, then translate { $translation }
exercise-name = exercise { $number } (seed { $seed })
sheet-rules-worksheet = the worksheet's rules (no scene ambient, no emission, M itself for normals)
sheet-rules-opengl = the rules of OpenGL 2.1's fixed function
sheet-rules-demo = the rules of the Phong demo's shader
sheet-compute = Compute the colour of the vertex step by step, under { $rules }.
sheet-colours = Colours are written as the worksheet writes them, [r g b 0], so every product of two colours has 0 as its fourth component, as in the key.
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
sheet-scene-file = Scene file: `{ $file }`.
key-title = Answers: { $name }
key-intro = As `phonglab explain { $file }` prints them (8 significant digits).
worked-calculation-of = Worked calculation: { $name }
exercise-zero-title = Exercise 0: the worksheet
exercise-zero-name = the worksheet
exercise-zero-intro = The worksheet's own scene (bronze, the light at (0, 0, 90), the vertex (-512, -384, 0) with normal (0, 0, 1)) under each of its five modelviews, `mview1` to `mview5`. Compute every step for each.
answers = answers
index-directional-only = one directional light only
exercise-effect-positional = a positional light
exercise-effect-attenuation = attenuation
exercise-effect-spot = a spotlight
exercise-effect-local-viewer = the local viewer
exercise-effect-two-sided = two-sided lighting
exercise-effect-several-lights = several lights
index-title = Exercises, seed { $seed }
index-intro = Effects: { $effects }. Rules: { $rules }. Each sheet has its scene file (open it in phonglab) and its answers.
index-printable = To print: [sheets.pdf](sheets.pdf) (to hand out: print it on both sides, and each exercise is its own sheet of paper) and [keys.pdf](keys.pdf) (the answers, for the teacher).
index-printable-one-sided = To print: [sheets.pdf](sheets.pdf) (to hand out: one page an exercise, so printed on one side each exercise is its own sheet of paper) and [keys.pdf](keys.pdf) (the answers, for the teacher).

## pdf

sheet-class = Class
sheet-name = Name
sheet-date = Date
pdf-page = page { $page } of { $pages }
pdf-blank-page = This page is left blank on purpose.

## cli

exercises-written =
    { $count ->
    [one] 1 exercise in { $out } ({ $redraws } draws set aside by the screen)
    *[other] { $count } exercises in { $out } ({ $redraws } draws set aside by the screen)
    }

## cli-out

render-summary = { $path }: { $size } px, { $triangles } triangles, { $covered } % covered, { $evaluations } lighting evaluations, { $ms } ms
render-channel-summary = channel { $channel } in { $map }: from { $low } to { $high }
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
probe-uncovered = Pixel ({ $x }, { $y }) shows no surface (the background).
err-probe-at = expected the pixel as X,Y (two whole numbers), got { $value }
err-probe-outside = pixel ({ $x }, { $y }) is outside the { $size }x{ $size } picture
probe = Probe
probe-hover = Why is this pixel this colour? Point at the picture; click to pin a pixel
probe-window = Pixel probe
probe-follows = Follows the pointer over the picture; click to pin a pixel.
probe-pinned = Pinned to the pixel clicked.
probe-unpin = Follow the pointer again
probe-hover-the-picture = Point at the shaded picture.
probe-open-vertex = Open vertex { $vertex }’s worked calculation
channel-show = Show
channel-picture = The picture
channel-hover = One term of the lighting equation at every pixel, in false colour (viridis), with its scale
channel-caption = term { $channel }
channel-legend-normal = The normal as a colour: x as red, y as green, z as blue, from -1 (dark) to 1 (bright)
channel-legend-luminance = { $channel }: the luminance (Rec. 709) of a colour term, before any clamp
channel-legend-range = { $what }, from { $low } to { $high }
channel-legend-attenuation = 1/at: the factor this light's terms are multiplied by (at = k0 + k1 d + k2 d², the worksheet's, divides)
channel-legend-spot = spot: the factor this light's terms are multiplied by (0 outside the cone, 1 without a spotlight)
channel-legend-n-dot-l = N·L = cos θ: a cosine, below 0 where the surface faces away from the light
channel-legend-n-dot-h = N·H = cos β: the specular cosine before its power (R·V under the Phong rule)
channel-legend-light-count = How many lights reach the pixel: a count
probe-attenuation-factor = Attenuation factor, what the terms are multiplied by
case-rules-note = note: { $path } uses the { $rules } rules; a case always means OpenGL's
cost-wrote = wrote { $files } in { $out }

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
toml-camera-takes = { $field }: a camera of kind = "{ $kind }" takes { $keys }
toml-camera-needs = camera: kind = "{ $kind }" needs { $keys }
toml-unknown-material = { $field }: unknown material { $name }; the classic materials are { $names }
toml-placement-needs-matrix = { $field }: placement = "matrix" needs placement_matrix (4 rows of 4)
toml-matrix-needs-placement = { $field }: placement_matrix needs placement = "matrix"
toml-control-character = { $field } holds the control character { $char } (character { $position }): a name or a path is one line of printable text
toml-unknown-field-one = unknown field { $field }, expected { $known }

## io-errors

io-not-found = it does not exist
io-permission-denied = permission denied
io-storage-full = the disk is full
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
write-step-create-file-in = create a file in
write-step-create-staging = create a staging folder in
write-step-list = list
write-step-lock-folder = lock the folder
write-step-recover = finish the set a stopped run left in
write-step-remove-journal = remove the journal of
write-step-killed = stop (killed) while writing
write-kept-file = the file there before (if any) is unchanged
write-kept-nothing = nothing was written
write-kept-folder = the folder is unchanged
write-kept-recoverable = the old set or the new one is whole, and the next run in this folder finishes what was started
write-not-a-regular-file = not a regular file (a link to nothing, a folder, a device or a pipe): phonglab writes only a regular file or a new one
set-folder-is-a-link = a link to another folder: phonglab writes a set of files only into a real folder, never through a link
set-left-alone = { $name } in { $dir } was left as it is: { $why }
set-why-loose-journal = a journal phonglab did not write there (planted, or left by an older phonglab); nothing it names was touched
set-why-not-a-folder = it is named like phonglab's staging folders but is not a folder phonglab made; nothing was followed or touched
set-why-no-journal = a folder named like phonglab's staging folders, without phonglab's journal; nothing in it was touched
set-untrusted-journal = its journal is not one phonglab wrote there ({ $why }); nothing was touched
set-why-not-a-journal = it is not a journal of phonglab's
set-why-other-folder = it names not the folder it is in
set-why-outside = it names files outside its folder
set-why-unfinished = a stopped run's files could not be put in place without replacing files changed or made since ({ $names }); its new files are kept in that folder
read-cannot = cannot read { $path }: { $reason }
read-not-a-file = { $path } is not a regular file
read-too-large = { $path } is { $size }; phonglab reads { $what } of at most { $cap }
read-not-utf8 = { $path } is not UTF-8 text (byte { $byte })
file-kind-scenes = scene files
file-kind-cases = case files
png-cannot-encode = cannot encode the PNG
png-too-large = image too large
png-colour-type = { $path }: unexpected colour type { $kind }
pdf-cannot-write = cannot write the PDF: { $error }
err-scale = --scale { $scale }: from 0.5 to 4
err-spin = --spin must be a finite number of degrees
err-threads = --threads { $asked }: this machine runs at most { $most } threads at once; ask for { $most } or fewer (0: one per core)
err-no-such-light = --light { $light }: { $count ->
    [0] the scene has no light
    [one] the scene has one light, number 0
   *[other] the scene has { $count } lights, numbered 0 to { $last }
}
err-study-stopped = the study stopped
err-rules = --rules { $value }: try worksheet or opengl
err-effects = --effects: { $value } is not one of { $names }
err-level = --level is 1 to 4
err-target = --target { $value }: try glsl or wgsl
err-shading = --shading { $value }: try gouraud or phong
err-not-case-file = not a case file
err-cases-failed = { $failed } of { $all } cases failed (their "error" says why)
err-unknown-preset = unknown preset { $value }: try { $names }
err-bench-frame-obj = --bench-frame draws the benchmark's sphere, teapot or cylinder; use --obj without it
err-scene-to-render = the scene to render
err-bench-object = --object { $value }: the benchmark's objects are sphere and teapot
err-bench-shading = --shading { $value }: the shadings are gouraud, phong and flat
err-bench-slices = --slices { $value }: the sphere takes 3 to 2048 slices (the benchmark's is 50)
err-bench-scan = --scan { $value }: the scan-like mesh takes levels 0 to 9 (8 gives 1 310 720 triangles)
err-study-timeout = the study did not finish in 5 minutes
err-output-is-input = { $output } is { $what } { $input }, which this command reads (the same file): writing it would destroy what is read; choose another output
err-output-is-other-output = { $output } is the other output { $other } (the same file): one would be written over the other; choose two different files
input-kind-input = the input
input-kind-scene = the scene
input-kind-mesh = the mesh
input-kind-code = the notebook or script
input-kind-cases = the case file
err-needs-window = this command draws the window: run it with the phonglab program
screenshot-summary = { $path }: { $width }x{ $height } px; pictures { $pictures } points, the plot's unit circle { $circle } points across, { $empty } % empty
screenshot-none = none
bench-render-header = phonglab bench render: { $size }x{ $size } px, { $frames } frames, { $threads } threads; the stages' mean ms: vertices, setup, raster, resolve
bench-lighting-header = phonglab bench lighting: { $vertices } vertices, best of { $repeats }, one thread, f32
bench-memory-floor = memory floor: the same arrays read and written with no lighting, { $ns } ns per vertex ({ $gbs } GB/s of the { $bytes } bytes a vertex moves)
bench-stages-header = where the specialised time goes (ns per vertex; reading the clock adds ~0.2 a step)
bench-ui-present-header = phonglab bench ui --present: { $width }x{ $height } points, presentation mode with the controls drawer out, { $frames } frames per case; each frame the light's z moves as a dragged slider moves it; CPU ms (layout includes the scene's evaluation and the shaded view's render)
bench-ui-header = phonglab bench ui: { $width }x{ $height } points, every panel open, { $frames } frames per case, CPU ms (layout includes the scene's evaluation and the shaded view's render when it changed)
err-lang = { $value }: phonglab speaks en, pt-PT and pt-BR
err-decimal = { $value }: point or comma

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

cost-axis-ms = ms per frame (log)
cost-axis-error = mean error, 1/255 (log)
cost-rounding = 8-bit rounding
cost-variant = variant
cost-triangles = triangles
cost-ms = ms/frame
cost-mean = mean /255
cost-max = max /255
cost-cheapest = Cheapest with under 1 % of pixels off by more than 1/255: { $variant } ({ $triangles } triangles), { $ms } ms per frame.
cost-none-within = No shading studied stays within 1/255 on 99 % of the pixels: the silhouette or the highlight needs a finer mesh.
cost-precision = f32 against f64 on { $vertices } vertices: at most { $apart } apart ({ $shown }/255 after clamping); the general engine takes { $f32 } ns (f32) and { $f64 } ns (f64) a vertex, the specialised one { $specialised } ns.
cost-intro = Each shading at five tessellations of the current object, timed and compared with a reference: per-pixel Phong in f64 on a very fine mesh. Also Phong in f32 on the reference's own mesh (does f64 change anything visible?) and the approximations people use.
cost-run = Run the study
cancel = Cancel
cost-about = { $about } ({ $size }x{ $size } px, timings taken while the app runs)
cost-table = Table
heat-map-computing = Error heat map: computing the reference...
heat-map-caption = Error against the f64 reference: mean { $mean }/255, max { $max }/255, { $share } % of pixels > 1/255 (white: { $white }/255)
cost-failed = The study failed: { $error }
heat-map-failed = The heat map failed: { $error }
work-starting = starting
work-failed = the computation failed unexpectedly
work-no-pool = no thread pool: { $error }
work-stopped = the computation stopped
cost-table-title = { $object }: { $size }x{ $size } px, reference { $triangles } triangles (f64, per pixel); errors in 1/255 against it
cost-over-column = >1/255 %
cost-chart-title = { $object }: time per frame against mean error ({ $size }x{ $size } px, reference: per-pixel Phong in f64, { $triangles } triangles)
cost-approx-llvmpipe-pow = llvmpipe pow
cost-approx-schlick-pow = Schlick pow
cost-approx-fast-rsqrt = fast rsqrt
cost-approx-no-renormalisation = no renormalisation

## cli

cli-about = An explorer for OpenGL's fixed-function vertex lighting and Gouraud/Phong/Flat shading
cli-lang = The language of what phonglab says: en, pt-PT or pt-BR (default: the system's, from LC_ALL, LC_MESSAGES or LANG). JSON, CSV and scene files keep English keys
cli-decimal = How numbers meant for people are written: point (0.5) or comma (0,5); default: the language's (a comma in Portuguese). Typed numbers are read with either
cli-memory-budget = The memory a command may take for what it is asked (a picture's size, a mesh): 512M, 8G, ...; default: half of what the system has available. Past it, a command says how much it needs and does not start
cli-eval = Evaluate glref cases (JSON) and print the lit colours as JSON
cli-explain = Print the worked calculation of a vertex, step by step, in the worksheet's order
cli-render = Render the shaded view (sphere, teapot or cylinder) to a PNG
cli-exercise = Write exercise sheets in the worksheet's style, with scene files and answer keys
cli-shader = Print the shader (GLSL 3.30 or WGSL) that draws a scene's shaded view: only the stages it needs
cli-case = Write scene files as glref cases (JSON), to check them against a real OpenGL
cli-cost = What accuracy costs: each shading and tessellation, f32 against f64 and the usual approximations, timed and compared with a per-pixel f64 reference; writes cost.csv and cost.png
cli-bench = Measure: the renderer, the lighting
cli-screenshot = Draw the whole window headless (no display, no GPU) to a PNG: for slides, handouts and the tests

## cli-args

cli-usage = Usage:
cli-heading-commands = Commands
cli-heading-arguments = Arguments
cli-heading-options = Options
cli-flag-help = Print help
cli-flag-version = Print version
cli-help-command = Print this message or the help of the given subcommand(s)
cli-default = [default: { $value }]
cli-possible-values = [values: { $values }]
cli-bench-render = ms per frame of the CPU renderer on the benchmark scene
cli-bench-lighting = ns per vertex of the general and the specialised lighting
cli-bench-ui = CPU time per frame of the whole UI, headless, with every panel open
cli-arg-app-file = A scene file (TOML) to open the app on; one that cannot be read opens the worksheet and says why
cli-arg-app-renderer = Who draws the app's shaded view: the GPU when the adapter is a real one, else the CPU renderer
cli-arg-eval-cases = A JSON file of cases (a list, or {"{"}"cases": [...]{"}"}), as in docs/lighting.md
cli-arg-eval-precision = Engine precision
cli-arg-eval-clamp = Clamp the colours to [0, 1] as OpenGL does by default (otherwise unclamped)
cli-arg-eval-pow = Power function for the specular and spot terms
cli-arg-explain-scene = A scene file (TOML), as the app saves it
cli-arg-explain-worksheet = The worksheet's scene with modelview N (1-5). The default when no scene is given: 5
cli-arg-explain-preset = A ready-made scene instead: "phong-demo"
cli-arg-explain-precision = Engine precision
cli-arg-explain-back = Explain the back side (two-sided lighting)
cli-arg-explain-markdown = Print a Markdown table instead of text
cli-arg-explain-digits = Significant digits
cli-arg-render-object = The object (default: the scene's)
cli-arg-render-obj = Shade this Wavefront OBJ mesh instead of the scene's object (fitted to radius 0.5)
cli-arg-render-shading = The shading (default: the scene's)
cli-arg-render-size = Image width and height in pixels
cli-arg-render-output = The PNG to write
cli-arg-render-scene = A scene file (TOML); default: the worksheet's scene
cli-arg-render-preset = A ready-made scene instead: "worksheet" or "phong-demo"
cli-arg-render-bench_frame = docs/lighting.md's benchmark scene at this frame instead (sphere r 1 50x50, teapot 0.8, gluPerspective(40, 1, 0.5, 20)): the image Mesa's harness draws
cli-arg-render-pow = Power function for the specular and spot terms
cli-arg-render-cull = Cull back faces
cli-arg-render-frame = Frame N of the scene's spin: N steps of 0.5 degrees (the Phong demo's first frame drawn is 1). Default: the scene's own spin
cli-arg-render-correct = Correct the Phong demo's departures from OpenGL's lighting (comma-separated): light (fixed in the world), normals (the surface's true ones), highlight (in the light's colour), or all
cli-arg-probe-object = The object (default: the scene's)
cli-arg-probe-obj = Shade this Wavefront OBJ mesh instead of the scene's object (fitted to radius 0.5)
cli-arg-probe-shading = The shading (default: the scene's)
cli-arg-probe-size = Image width and height in pixels
cli-arg-probe-scene = A scene file (TOML); default: the worksheet's scene
cli-arg-probe-preset = A ready-made scene instead: "worksheet" or "phong-demo"
cli-arg-probe-bench_frame = docs/lighting.md's benchmark scene at this frame instead (sphere r 1 50x50, teapot 0.8, gluPerspective(40, 1, 0.5, 20)): the image Mesa's harness draws
cli-arg-probe-pow = Power function for the specular and spot terms
cli-arg-probe-cull = Cull back faces
cli-arg-probe-frame = Frame N of the scene's spin: N steps of 0.5 degrees (the Phong demo's first frame drawn is 1). Default: the scene's own spin
cli-arg-probe-correct = Correct the Phong demo's departures from OpenGL's lighting (comma-separated): light (fixed in the world), normals (the surface's true ones), highlight (in the light's colour), or all
cli-probe = Why one pixel of the shaded view is its colour: its triangle, weights, vertices or fragment, every term, the clamp and the 8-bit rounding
cli-arg-probe-at = The pixel: x from the left, y from the top, from 0
cli-arg-probe-json = Print JSON (for scripts and tests) instead of the report
cli-arg-render-channel = Draw one term of the lighting equation in false colour instead of the picture
cli-arg-render-light = The channel's light, by its place among the enabled lights (0 the first); the colour terms sum every light when it is left out
cli-arg-render-colour_map = The false colour's map
cli-arg-render-raw = Also write the channel's values, unclamped, as a portable float map (PFM)
cli-share = A scene as a link to the browser build (the scene in the link itself), and as a QR code for a class
cli-arg-share-scene = The scene file (TOML); default: the worksheet's scene
cli-arg-share-base = The page the link opens
cli-arg-share-open_in = Open it in this language (en, pt-PT, pt-BR)
cli-arg-share-present = Open it presenting to a class
cli-arg-share-channel = Open it showing this term in place of the picture
cli-arg-share-qr = Also write the link as a QR code: FILE.png or FILE.svg
cli-value-emission = the material's emission, e_cm
cli-value-scene-ambient = the scene's ambient, a_cm a_cs
cli-value-ambient = each light's ambient, after attenuation and spot
cli-value-diffuse = each light's diffuse, after attenuation and spot
cli-value-specular = each light's specular, after attenuation and spot
cli-value-attenuation = one light's attenuation factor, 1/at (the worksheet's at = k0 + k1 d + k2 d² divides)
cli-value-spot = one light's spot factor
cli-value-n-dot-l = one light's n · L
cli-value-n-dot-h = one light's n · H
cli-value-normal = the normal the pixel is lit with, as a colour
cli-value-light-count = how many lights reach the pixel
cli-value-viridis = viridis (dark blue, green, yellow)
cli-value-cividis = cividis (blue to yellow), made for red-green colour blindness
cli-arg-exercise-seed = The random seed: the same seed gives the same sheets
cli-arg-exercise-count = How many exercises
cli-arg-exercise-level = Difficulty: 1 directional only, 2 positional with attenuation, 3 spotlights, 4 two-sided with several lights
cli-arg-exercise-effects = Exactly these effects instead of a level (comma-separated): positional, attenuation, spot, local-viewer, two-sided, several-lights
cli-arg-exercise-rules = The rules the answers follow: worksheet or opengl
cli-arg-exercise-worksheet = Also write exercise 0: the worksheet itself, its five modelviews on one sheet
cli-arg-exercise-out = The folder to write to (created if missing)
cli-arg-shader-scene = A scene file (default: the worksheet's, mview5)
cli-arg-shader-target = glsl (3.30 core: a vertex and a fragment shader) or wgsl (one module)
cli-arg-shader-shading = gouraud (lit per vertex) or phong (lit per fragment)
cli-arg-case-scenes = Scene files (TOML); each becomes one case, its id the file's stem
cli-arg-cost-object = The object to study (default: all three)
cli-arg-cost-out = Where to write cost.csv, cost.png and the heat maps
cli-arg-cost-size = Image width and height in pixels
cli-arg-cost-scene = A scene file (TOML) for the lighting and the view; default: the worksheet's scene
cli-arg-cost-spin = Turn the object this many degrees about y (the cylinder shows its side at 30)
cli-arg-cost-threads = Threads for rendering (default: all cores)
cli-arg-cost-quick = Quick timings (3 frames or 0.1 s per variant) instead of careful ones
cli-arg-bench-render-frames = Frames timed per object and shading (after 5 warm-up frames)
cli-arg-bench-render-size = Image size in pixels (square)
cli-arg-bench-render-threads = Worker threads (default: one per core)
cli-arg-bench-render-object = Only this object: sphere or teapot (default: both)
cli-arg-bench-render-shading = Only this shading: gouraud, phong or flat (default: all three)
cli-arg-bench-render-slices = The sphere's slices and stacks, 3 to 2048 (the benchmark's is 50): the cost against the triangle count
cli-arg-bench-render-mesh = Time this OBJ mesh (fitted to the view) instead of the sphere and the teapot
cli-arg-bench-render-scan = Time the scan-like mesh of 20 x 4^LEVEL triangles (a bumpy, irregular subdivided icosahedron; 8 gives 1 310 720) instead of the sphere and the teapot
cli-arg-bench-render-write_mesh = Write the mesh that would be timed (--mesh, --scan or the sphere of --slices, as placed in the benchmark's view) as an OBJ file, and time nothing: the very vertex arrays for Mesa's harness (benches/compare_llvmpipe.py)
cli-arg-bench-render-moving = What changes from frame to frame: object (it turns 3 degrees a frame, every frame drawn whole) or light (it circles the standing object, as when a student drags it: the visibility is kept and only lighting and shading run again)
cli-arg-bench-render-coarse = Time the coarse copy of about this many triangles instead of the mesh itself: what the app draws while the camera turns over a very large mesh (it says how long the copy took to make)
cli-arg-bench-lighting-vertices = Vertices per scene
cli-arg-bench-lighting-repeats = Timed repetitions (the best is reported)
cli-arg-bench-lighting-stages = Also say where the specialised lighting's time goes: ns per vertex for loading, each stage of the scene's program, and writing
cli-arg-bench-ui-frames = Frames timed per case
cli-arg-bench-ui-width = Window width in points
cli-arg-bench-ui-height = Window height in points
cli-arg-bench-ui-present = Presentation mode (large type, the controls drawer out) at 1920x1080 unless a size is given: the light is dragged with Gouraud and then with Phong shading
cli-arg-screenshot-size = The window's size in points, WIDTHxHEIGHT
cli-arg-screenshot-scale = Pixels per point (2 for a high-density screen)
cli-arg-screenshot-present = Presentation mode (F5)
cli-arg-screenshot-light = The light theme (default: dark)
cli-arg-screenshot-scene = A scene file (default: the worksheet's scene)
cli-arg-screenshot-open = Open this first
cli-arg-screenshot-output = The PNG to write
cli-value-auto = the GPU when the adapter is a real one, else the CPU renderer
cli-value-cpu = the CPU renderer (the reference)
cli-value-gpu = the GPU, even a software adapter
cli-value-f32 = single precision, as OpenGL computes
cli-value-f64 = double precision
cli-value-exact = the exact library pow
cli-value-llvmpipe = Mesa llvmpipe's exp2(e log2 x) approximation, bit-exact with Mesa 22.3
cli-value-schlick = Schlick's rational approximation
cli-value-sphere = gluSphere
cli-value-teapot = the Utah teapot
cli-value-cylinder = gluCylinder
cli-value-gouraud = per-vertex lighting, colours interpolated
cli-value-phong = per-pixel lighting
cli-value-flat = one evaluation per face
cli-value-light = the light fixed in the world
cli-value-normals = the surface's true normals
cli-value-highlight = the highlight in the light's colour
cli-value-all = all three
cli-value-compare = Compare, with the scene pinned as A and B the same scene in Phong shading
cli-value-lobe = the reflection lobe in the plot's place
cli-value-quiz = the quiz on the scene
cli-value-shader = the Shader window
cli-value-cost = the Cost of accuracy window
cli-value-demo-fixes = the Phong demo's three corrections, side by side with the demo's own picture
app-cannot-open-window =
    cannot open the window: { $error }
    (headless? the subcommands work without a display: phonglab --help)

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

## phonglab check: a student's work checked
check-no-outputs = this notebook was saved without its outputs: nothing it printed can be checked. Run it first (Jupyter: Kernel → Restart & Run All), save it, and check it again
check-verdict-right = right
check-verdict-right-given = right, given your { $step }
check-verdict-rounding = rounding
check-verdict-wrong = wrong
check-rules = rules assumed: { $rules }
check-inputs-differ = your typed inputs differ from the assignment's: { $names }
check-step = { $step }: yours { $student }, the key's { $key }: { $verdict }
check-first-wrong = first wrong step: { $step } (yours { $student }, the key's { $key })
check-all-right = all right: every step printed is the key's
check-cause = likely cause: { $words } [{ $id }]. Evidence: at { $step } you printed { $student }, and the key with this mistake gives { $value }
check-no-cause = no mistake in the catalogue reproduces everything you printed; look at the first wrong step
check-nothing-printed = nothing printed that the key has: print each value as the worksheet does, print("vlv = ", vlv)
check-cause-normal-by-modelview = the normal transformed by the modelview M instead of its inverse transpose (wrong under a non-uniform scale)
check-cause-normal-not-normalised = the normal not normalised after its transform
check-cause-light-not-transformed = the light's position not transformed by the modelview (left in object space)
check-cause-light-transformed-twice = the light's position transformed by the modelview twice
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
check-report-title = Class check
check-report-student = Student
check-report-verdict = Verdict
check-report-first-wrong = First wrong step
check-report-causes = Causes
check-report-counts = Causes in the class
check-report-unexplained = not explained by the catalogue
check-report-unreadable = not read: { $reason }
check-report-written = checked { $count } submissions: { $path }
check-chart-title = Causes in the class ({ $count } submissions)
check-verdict-word-right = right
check-verdict-word-wrong = wrong
cli-check = Check a student's work: a worksheet notebook with its outputs, a script's printed text, or a folder of them; each printed step against the key, the first wrong step and its likely causes
cli-arg-check-work = The notebook (.ipynb, saved with its outputs), or a folder of them for the whole class
cli-arg-check-printed = The text a script printed, instead of a notebook (- for the standard input)
cli-arg-check-scene = The assignment's scene (TOML); default: the notebook's own (the worksheet's for printed text)
cli-arg-check-json = Write the check as JSON
cli-arg-check-report = For a folder: the class report to write (Markdown), with its bar chart beside it (.png)
cli-arg-check-csv = For a folder: the marks to write (CSV)
