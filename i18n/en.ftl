# phonglab's app messages in English: the window's, the command line's and the files'.
# The core's messages are in crates/phonglab-core/i18n/en.ftl.

## app

language-menu-hover = Language, and how numbers are written (0,5 or 0.5)
leave-presenting = Leave (F5)
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
director-eye = eye
director-vertex = vertex
director-light = light { $n }
director-legend = at the vertex, one length each (their true directions in this space); blue square: the near plane (the viewport); green square: the surface at the vertex. Drag a light or the eye to move it; drag elsewhere to turn; scroll to zoom.
director-naive-normal = Dotted, in light blue: M n, the normal moved as a point would be, { $degrees }° off the true normal (M^-1)^T n, which stays perpendicular to the surface.
director-rules-naive = This scene's rules (the worksheet's) light the vertex with M n; OpenGL's use (M^-1)^T n.
director-ring = Light { $n }: 1/at, the attenuation factor, falls to { $percent } % at distance { $distance } (a ring).
wrong-title = What is wrong with this picture?
wrong-intro = Each sheet shows a sphere drawn right and drawn with one mistake. Pick the mistake; the key explains it with the pixel probe’s numbers.
wrong-sheet-title = What is wrong with this picture? ({ $number })
wrong-drawn-right = Drawn right
wrong-drawn-wrong = Drawn with one mistake
wrong-question = Which one mistake makes the right-hand picture? Tick it, and say what in the picture shows it.

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

## controls

controls-rules = Rules
controls-lights = Lights
controls-material = Material
controls-light-model = Light model
controls-vertex = Vertex
controls-camera = Camera (modelview)
rule-set = Rule set
specular-model = Specular model
rules-opengl-summary = Emission + scene ambient + every light's ambient, diffuse and specular (OpenGL 2.1, 2.14.1).
rules-worksheet-summary = The worksheet: no scene ambient, no emission; diffuse 0 past 90 degrees, specular 0 past 90 degrees.
rules-demo-summary = The Phong demo's shader: no scene ambient, no emission, pow(max(R.V, 0), e) with no other gate.
placement-eye = the eye (moves with the camera)
placement-world = the world
placement-object = the object (turns with it)
placement-matrix = a typed matrix
add-light = Add light
remove-light = Remove light
lights-of-max = { $count } of { $max }
no-lights = No lights: only emission and the scene ambient remain.
directional = Directional (w = 0)
light-x = Light x
light-y = Light y
light-z = Light z
light-fixed-to = Light fixed to
attenuation-positional-only = Attenuation applies to positional lights only.
spotlight = Spotlight
spotlight-hover = A new spotlight aims at the object in the view
material-custom = custom
material-preset = Material preset
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
separate-specular = Separate specular colour
normals-as-is = as transformed
normals = Normals
normalise-normal = Normalise the normal
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
dark-vertex = a dark vertex: { $percent } % as bright as white
dark-vertex-angle = a dark vertex: { $percent } % as bright as white; the light meets it at { $angle }°
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

## help

help-help = show or hide this help
help-present = present: large type, the controls in a drawer (F5 again to leave)
help-walk-steps = walk through the calculation's steps, one at a time (when no field has the keyboard)
help-zoom = zoom the whole window in, out, back to 100 %
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
quiz-close-key = ≈ close: { $percent } % from the key; give { $digits } significant digits
quiz-close-yours = ≈ close: { $percent } % from what your earlier answers give; give { $digits } significant digits
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
quiz-instructions = { $scene }: type each step's value and press Enter. Right: within { $percent } % of the value (or { $absolute } near 0). A point or a comma; a vector as 0,5; 0,3; 0,1.
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

## calculation

plan-heading = Specialised plan: { $computed ->
        [one] 1 effect computed
       *[other] { $computed } effects computed
    }, { $skipped } skipped
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
mesh-triangles =
    { $count ->
        [one] 1 triangle
       *[other] { $count } triangles
    }: { $notes }
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
mesh-file-hint = path/to/mesh.obj
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
mesh-summary =
    { $triangles ->
        [one] 1 triangle
       *[other] { $triangles } triangles
    }, { $vertices } vertices; { $notes }
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

err-export-folder = openframeworks writes three files: give a folder with -o (they go into its src/)
export-written = written: { $path }
bench-mesh-written = mesh written: { $path } ({ $triangles } triangles, { $vertices } vertices)
bench-coarse-made = { $object }: the coarse copy has { $triangles } of { $all } triangles, made in { $ms } ms
import-written = scene written: { $path } ({ $lights })
budget-over = { $what } needs about { $needed }, more than the memory budget of { $budget } ({ $from }); --memory-budget SIZE raises it: this run needs --memory-budget { $suggest } or more
budget-from-option = as --memory-budget asks
budget-from-option-bare = as --memory-budget { $number } asks: a size without a unit counts bytes; { $number } MiB is --memory-budget { $number }M
budget-from-system = half of the memory available
budget-from-limit = half of the address space left under this process's limit, ulimit -v
budget-over-limit = --memory-budget { $budget } is more than this process may still take under its limit, ulimit -v ({ $room } left): a run past it would stop half-way. Lower --memory-budget, or raise the limit (ulimit -v)
budget-size-negative = { $value }: a size cannot be negative; write a size such as 512M, 8G or 1.5G
budget-size-refused = { $value }: write a size such as 512M, 8G or 1.5G
budget-what-render = a { $width } x { $height } picture of { $count ->
        [one] one triangle
       *[other] { $triangles } triangles
    }
budget-what-window = the window at { $width } x { $height } pixels
budget-what-diagnose = comparing a { $size } x { $size } picture with { $count } drawings, one at a time,
budget-what-check = checking { $count ->
    [one] one submission of { $largest }
   *[other] { $count } submissions, the largest { $largest },
}
budget-what-cost = the study of { $count ->
    [one] one object
   *[other] { $count } objects
} at { $size } x { $size } pixels
budget-what-eval = lighting { $count ->
    [one] one case of { $largest }
   *[other] { $count } cases, one at a time, the largest { $largest }
} of JSON
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
export-code = Your own code
export-copy = Copy
export-copy-hover = Copy it to the clipboard (the notebook as one script, the openFrameworks files one after the other)
export-save = Save…
export-save-hover = Save it as a file (openFrameworks: a zip of the project's src/)
export-copied = Copied: { $what }
export-nothing = nothing to write
export-import-hint = To go the other way, open or drop a worksheet notebook (.ipynb) or script (.py): its values become the scene.
imported = Opened { $path } as a scene (the worksheet's rules unless it says otherwise).{ $notices }

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
compare-difference-legend = Each channel's difference, times { $gain }: a channel is at full strength from { $full }/255 on (white where all three are, black where A and B agree). { $percent } % of the object's pixels differ by more than { $visible }/255; the largest difference is { $largest }/255.
compare-step-1 = 1. Pin the current scene as A (the button above).
compare-step-2 = 2. Change anything: the shading, f32 or f64, the material, a light.
compare-step-3 = 3. A and B show side by side, with the steps that differ first.
compare-a-fails = A cannot be evaluated: { $error }
compare-differing = { $differing ->
    [one] 1 of { $all } steps differs: it comes first, highlighted.
   *[other] { $differing } of { $all } steps differ: they come first, highlighted.
}
compare-none-differ = Nothing differs: A and B give the same value at each of the { $all } steps.
copy = Copy
copy-program-hover = Copy the program to the clipboard
shader-stages-phong = Phong (per fragment) shading: only the stages this scene needs
shader-stages-vertex = per vertex shading: only the stages this scene needs
shader-last-change = The last change added { $added ->
        [one] 1 line
       *[other] { $added } lines
    } (highlighted) and removed { $removed }.
shader-removed = Removed by the last change:
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

sheet-scene-file = Scene file: `{ $file }`.
key-title = Answers: { $name }
key-intro = As `phonglab explain { $file }` prints them (8 significant digits).
worked-calculation-of = Worked calculation: { $name }
exercise-zero-title = Exercise 0: the worksheet
exercise-zero-name = the worksheet
exercise-zero-intro = The worksheet's own scene (bronze, the light at (0, 0, 90), the vertex (-512, -384, 0) with normal (0, 0, 1)) under each of its five modelviews, `mview1` to `mview5`. Compute every step for each.
answers = answers
index-directional-only = one directional light only
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
        [one] 1 exercise
       *[other] { $count } exercises
    } in { $out }{ $redraws ->
        [0] {""}
        [one] {" "}(1 draw rejected: it lacked an asked effect or hit an edge case)
       *[other] {" "}({ $redraws } draws rejected: they lacked an asked effect or hit an edge case)
    }

## moodle-exam

exam-key-heading = Each value exact and rounded
exam-sheet-name = exam exercise { $number }
moodle-category-exercise = exercise { $number }
moodle-question-name = { $exercise }, variant { $variant }: key exercise-{ $sheet }-key.md of { $command }
moodle-category-default = phonglab
moodle-written = { $file } in { $out }: { $questions ->
    [one] one question
   *[other] { $questions } questions
} in { $categories ->
    [one] one category
   *[other] { $categories } categories
}. In Moodle: Question bank → Import → { $format }.
moodle-format-xml = Moodle XML format
moodle-format-gift = GIFT format
exam-key-exact = exact
exam-key-rounded = rounded to four significant digits
err-exam-level-5 = --exam makes exercises of levels 1 to 4; level 5 has pictures, not numbers.
err-moodle-only = --variants and --category are for a file for Moodle (--format moodle-xml or gift); sheets take --count.
err-level-5-variants = --variants is for levels 1 to 4: level 5 has one picture per mistake, seven in all, none drawn twice; use --count (1 to 7).
level-5-count = Level 5 has { $all } mistakes, one question each: { $all } questions, not { $count }.
wrong-written = { $count ->
    [one] 1 picture with one mistake, with its key,
   *[other] { $count } pictures with one mistake each, with their keys,
} in { $out }
wrong-quiz-hover = A sphere drawn right and drawn with one mistake: pick the mistake
wrong-check = Check
wrong-right-answer = Right.
wrong-wrong-answer = Not that one. The key:
wrong-back = Back to the calculation
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
share-needs-mesh = The link's scene shows the mesh { $name }, which a link does not carry: open or drop { $name } to see it (the sphere stands in until then).
mesh-not-kept = (Not kept for a reload of the page: { $why }; open it again after one.)
mesh-too-large-to-keep = packed, it is { $packed } characters, and the page keeps at most { $most }
mesh-not-restored = The mesh { $name } this page kept could not be read back ({ $why }): open it again.
quiz = Quiz
quiz-hover = Every value of the calculation behind a field: type them step by step
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

## cli-out

render-summary = { $path }: { $size } px, { $triangles } triangles, { $covered } % covered, { $evaluations } lighting evaluations, { $ms } ms
render-channel-summary = channel { $channel } in { $map }: from { $low } to { $high }
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
channel-legend-n-dot-h = N·H = cos β: the specular cosine before its power (Blinn-Phong's rule; R·V under Phong)
channel-legend-r-dot-v = R·V: the specular cosine before its power (Phong's rule; N·H under Blinn-Phong)
channel-legend-light-count = How many lights reach the pixel: a count
case-rules-note = note: { $path } uses the { $rules } rules; a case always means OpenGL's
cost-wrote = wrote { $files } in { $out }

## io-errors

set-folder-is-a-link = a link to another folder: phonglab writes a set of files only into a real folder, never through a link
set-folder-replaced = moved or replaced (by a link or another folder) while phonglab was writing the set: nothing was written, moved or removed through it (phonglab held the folder itself); the set was not written, and what it had begun was removed from the folder it held
set-staging-replaced = phonglab's working folder { $name } in it was moved or replaced (by a link or another folder) while phonglab was writing the set: nothing was written, moved or removed through it (phonglab held the working folder itself); the set was not written
set-staging-taken = phonglab's working folder { $name } was moved or replaced (by a link or another folder) the moment phonglab made it, before it was opened: nothing was written, moved or removed in it or through it; the set was not written
set-folder-replaced-asked = moved or replaced (by a link or another folder) while phonglab was writing the set. phonglab asks, before each step it takes by the folder's name, that it is still the folder it holds, and stopped at the first that was not (a program outside Windows' rules, as a Unix program under Wine, can rename a folder Windows holds); the set was not written, and what phonglab had moved it moved back where the folders allowed
set-staging-replaced-asked = phonglab's working folder { $name } was moved or replaced (by a link or another folder) while phonglab was writing the set. phonglab asks, before each step it takes by a folder's name, that it is still the folder it holds, and stopped at the first that was not (a program outside Windows' rules, as a Unix program under Wine, can rename a folder Windows holds); the set was not written. { $now }
set-staging-now-at = phonglab found that working folder at { $path }, by its identity: anything it could not move back or remove is there
set-staging-now-gone = That working folder is no longer where phonglab made it, and phonglab cannot say where it is: whatever phonglab could not move back is in it
set-held-folder-moved = phonglab's folder { $name } was moved or replaced (by a link or another folder) while phonglab was working in it: phonglab asks before each step it takes by the folder's name that it is still the folder it holds, and did not take this step
set-record-not-one = a link, or not a regular file phonglab can have written (a pipe, a device, a folder, or a file over 1 MiB), where phonglab keeps its list of the files it wrote in this folder: phonglab never reads or writes through it. Remove it, or choose another folder
set-record-not-phonglabs = not a list phonglab wrote (it is not in phonglab's form: written by hand or by another program), where phonglab keeps its list of the files it wrote in this folder: phonglab does not trust it, so it cannot tell which files here it wrote, and leaves it as it is. Remove it, or choose another folder
set-record-not-own = not this user's alone (another user owns it, or others may write it), where phonglab keeps its list of the files it wrote in this folder: anyone can write a list in phonglab's form, so phonglab trusts one only when no one else can have written it; it cannot tell which files here it wrote, and leaves the list as it is. Nothing was written, moved or removed. If you did not put it there, another user did: look at it, remove it, or choose another folder
set-waiting-for-lock = waiting: another phonglab is writing into { $dir }; this one goes on when it has finished
set-staging-left = the new set is whole in { $dir }; phonglab's working folder { $name } in it could not be removed yet (a file in it may still be open in another program): the next run in this folder removes it
set-left-alone = { $name } in { $dir } was left as it is: { $why }
set-name-differs-in-case = { $other } is there, a name that differs from the set's { $name } only in case: Windows takes the two for one file, so the set could replace or lose the wrong one. Rename or move { $other }, or choose another folder
set-file-replaced-meanwhile = it was replaced while phonglab was writing the set (by a link, or a file phonglab did not write): it was left as it is, and nothing of the new set was put in place
set-why-not-all-own = it holds something phonglab did not put there (a link, a folder or a file): that was left as it is, with the folder. Look at it, and delete it when it is not yours
set-why-loose-journal = a journal phonglab did not write there (planted, or left by an older phonglab); nothing it names was touched
set-why-not-a-folder = it is named like phonglab's staging folders but is not a folder phonglab made; nothing was followed or touched
set-why-no-journal = a folder named like phonglab's staging folders, without phonglab's journal; nothing in it was touched
set-untrusted-journal = its journal is not one phonglab wrote there ({ $why }); nothing was touched
set-why-not-a-journal = it is not a journal of phonglab's
set-why-not-own = it is not this user's alone (another user owns it, or others may write it), and anyone can write a journal in phonglab's form
set-why-folder-not-own = a folder named like phonglab's staging folders that is not this user's alone (another user made it, or others may write into it): phonglab trusts nothing in it; nothing in it was touched
set-why-other-folder = it names not the folder it is in
set-why-outside = it names files outside its folder
set-why-unfinished = a stopped run's files could not be put in place without replacing files changed or made since ({ $names }); its new files are kept in that folder
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
err-effects = --effects: { $value } is not one of: { $names }
err-effects-empty = --effects has an empty name (a comma with nothing after it or before it): write the names from { $names }, separated by commas.
err-out-is-a-file = --out { $out } is a file, and phonglab exercise writes its files into a folder: give a folder, or the name of a new one (nothing was written).
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
err-needs-window = this command draws the window: run it with the phonglab program
screenshot-summary = { $path }: { $width }x{ $height } px; pictures { $pictures } points, the plot's unit circle { $circle } points across, { $empty } % empty
screenshot-none = none
bench-render-header = phonglab bench render: { $size }x{ $size } px, { $frames } frames, { $threads } threads; the stages' mean ms: vertices, setup, raster, resolve
bench-lighting-header = phonglab bench lighting: { $vertices } vertices, best of { $repeats }, one thread, f32
bench-memory-floor = memory floor: the same arrays read and written with no lighting, { $ns } ns per vertex ({ $gbs } GB/s of the { $bytes } bytes a vertex moves)
bench-stages-header = where the specialised time goes (ns per vertex; reading the clock adds ~0.2 a step)
bench-ui-present-header = phonglab bench ui --present: { $width }x{ $height } points, presentation mode with the controls drawer out, { $frames } frames per case; each frame the light's z moves as a dragged slider moves it; CPU ms (layout includes the scene's evaluation and the shaded view's render)
bench-ui-header = phonglab bench ui: { $width }x{ $height } points, every panel open, { $frames } frames per case, CPU ms (layout includes the scene's evaluation and the shaded view's render when it changed)
err-lang = { $value }: phonglab speaks en, pt-PT and pt-BR
err-decimal = { $value }: point or comma

## cost

cost-axis-ms = ms per frame (log)
cost-axis-error = mean error, 1/255 (log)
cost-rounding = 8-bit rounding
cost-variant = variant
cost-triangles = triangles
cost-ms = ms/frame
cost-mean = mean /255
cost-max = max /255
cost-cheapest = Cheapest with under 1 % of pixels off by more than 1/255: { $variant } ({ $triangles } triangles), { $ms } ms per frame.
cost-none-within = No shading studied stays within 1/255 on 99 % of the pixels: the silhouette or the highlight needs a finer mesh.
cost-precision = f32 against f64 on { $vertices } vertices: at most { $apart } apart ({ $shown }/255 after clamping); the general engine takes { $f32 } ns (f32) and { $f64 } ns (f64) a vertex, the specialised one { $specialised } ns.
cost-intro = Each shading at five tessellations of the current object, timed and compared with a reference: per-pixel Phong in f64 on a very fine mesh. Also Phong in f32 on the reference's own mesh (does f64 change anything visible?) and the approximations people use.
cost-run = Run the study
cancel = Cancel
cost-about = { $about } ({ $size }x{ $size } px, timings taken while the app runs)
cost-table = Table
heat-map-computing = Error heat map: computing the reference...
heat-map-caption = Error against the f64 reference: mean { $mean }/255, max { $max }/255, { $share } % of pixels > 1/255 (white: { $white }/255)
cost-failed = The study failed: { $error }
heat-map-failed = The heat map failed: { $error }
work-starting = starting
work-failed = the computation failed unexpectedly
work-no-pool = no thread pool: { $error }
work-stopped = the computation stopped
cost-table-title = { $object }: { $size }x{ $size } px, reference { $triangles } triangles (f64, per pixel); errors in 1/255 against it
cost-over-column = >1/255 %
cost-chart-title = { $object }: time per frame against mean error ({ $size }x{ $size } px, reference: per-pixel Phong in f64, { $triangles } triangles)

## cli

cli-about = An explorer for OpenGL's fixed-function vertex lighting and Gouraud/Phong/Flat shading
cli-lang = The language of what phonglab says: en, pt-PT or pt-BR (default: the system's: LC_ALL, LC_MESSAGES or LANG where one is set, else on Windows the user's display language and on macOS their preferred language). JSON, CSV and scene files keep English keys
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
cli-arg-app-file = A scene file (TOML) to open the app on; one that cannot be read opens the worksheet and says why (a word without a dot that names no file is taken for a mistyped command)
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
cli-arg-exercise-level = Difficulty: 1 directional only, 2 positional with attenuation, 3 spotlights, 4 two-sided with several lights; 5 "what is wrong with this picture?" (one picture per mistake, seven at most)
cli-arg-exercise-effects = Exactly these effects instead of a level (comma-separated): positional, attenuation, spot, local-viewer, two-sided, several-lights
cli-arg-exercise-rules = The rules the answers follow: worksheet or opengl
cli-arg-exercise-worksheet = Also write exercise 0: the worksheet itself, its five modelviews on one sheet
cli-arg-exercise-out = The folder to write to (created if missing)
cli-arg-exercise-format = What to write: the sheets, keys and PDFs; or a file for Moodle's question bank
cli-arg-exercise-variants = With a Moodle format: this many seeded variants of each exercise, one category per exercise, for a quiz's random question
cli-arg-exercise-category = With a Moodle format: the name of the top category (phonglab by default)
cli-arg-exercise-exam = Exam exercises, worked without a calculator: Pythagorean unit vectors, whole distances, shininess 1, 2 or 4, four significant digits by hand
cli-value-sheets = sheets, keys, scene files and the two PDFs
cli-value-moodle-xml = questions.xml in Moodle XML: one Cloze question per exercise, pictures embedded
cli-value-gift = questions.gift.txt in GIFT: one numerical question per value
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
cli-stopped = { $how ->
        [ctrl-c] stopped by Ctrl+C.
       *[asked] stopped: the system asked it to end.
    } No file is left half-written (each is written whole or not at all); run the command again for what it had not yet written.
app-cannot-open-window =
    cannot open the window: { $error }
    (headless? the subcommands work without a display: phonglab --help)

## phonglab diagnose: a student's picture checked

cli-diagnose = A student's picture of a scene, checked: right, which mistake made it, or none phonglab knows; a difference image and the probe where it differs most. Exit code: 0 right, 1 wrong or unexplained, 2 a usage or input error
cli-arg-diagnose-scene = The scene the picture was made for (TOML)
cli-arg-diagnose-image = The student's picture (PNG), made with the export's camera and size
cli-arg-diagnose-size = The picture's width and height in pixels: the export's window is 512
cli-arg-diagnose-diff = Write the difference image (the picture against the right one) to this PNG
cli-arg-diagnose-json = Print JSON (for scripts and tests) instead of the report
file-kind-pictures = pictures
diagnose-bad-png = { $path } cannot be read as a PNG picture: { $reason }
diagnose-transparent = { $path } has { $count } transparent or see-through pixels (alpha below 255): what they show depends on what lies behind them, so phonglab does not judge it. Save the picture opaque, as the export and a screenshot of the window save it.
png-reason-jpeg = it is a JPEG picture, and phonglab diagnoses PNG only (a JPEG's losses can hide the cause): save the picture as PNG straight from the program (the exported program's --png option), or convert it (convert picture.jpg picture.png)
png-reason-not-png = it is not a PNG file (it does not start as one does)
png-reason-too-large = it is too large to decode
png-reason-damaged = the file is damaged or cut short
png-reason-colours = its colours are stored as { $kind }, which phonglab does not read
diagnose-wrong-size = { $path } is { $got } pixels; the picture of this scene is { $expected }. Save the program's PNG with its --png option, which draws the scene at that size: a screenshot of a window is not the drawing. (For a scene drawn at another size, phonglab diagnose --size checks it.)
diagnose-invisible = Not told apart from the right picture (in this scene each draws within what a picture can tell of it): { $ids }
diagnose-diff-written = Difference image written to { $path }: { $said }
diagnose-diff-not-png = --diff { $path }: a difference image is a PNG, and its name must end in .png (check would read a name ending in .ipynb, .py or .txt as a student's work); nothing was written.
diagnose-worst = The pixel that differs most: ({ $x }, { $y }), your picture { $image } against the right one { $right }. The probe of the right picture there:

## phonglab check: a student's work checked

check-nothing-printed = nothing printed that the key has: print each value as the worksheet does, print("vlv = ", vlv)
check-report-scene = Assignment: { $scene }
check-report-title = Class check
check-report-student = Student
check-report-verdict = Verdict
check-report-first-wrong = First wrong step
check-report-causes = Causes
check-report-counts = Causes in the class
check-report-unexplained = not explained by the catalogue
check-report-unreadable = not read: { $reason }
check-class-checked = checked { $count ->
    [one] one submission
   *[other] { $count } submissions
}{ $unread ->
    [0] {""}
    [one] {", "}one not read
   *[other] {", "}{ $unread } not read
}
check-class-report-written = report written to { $path } (its chart: { $chart })
check-class-marks-written = marks written to { $path }
check-printed-with-folder = --printed checks one script's printed text; a folder's notebooks are read from their own outputs: give one or the other
check-report-needs-folder = --report and --csv are a class's: give a folder of notebooks (one notebook's check is printed, or written as --json)
check-not-read-time = not read: the class's check took its { $seconds } s (the smallest files are checked first)
check-too-many-notebooks = { $folder } names more than { $max } notebooks: not a class's folder; nothing was checked or written
check-not-read-link = a link (a submission must be a file in the folder itself)
check-not-read-folder = a folder (a submission is a notebook file)
check-not-read-not-a-file = not a regular file (a FIFO or a device: a submission is a notebook file)
check-chart-link = { $path } is a link: the chart's name comes from the report's, and phonglab never writes through a link it was not given; remove the link or name another report
work-output-link = { $path } is a link: check and diagnose never write through a link, which could lead to any file (in a class folder a student may have put it there); nothing was written. Remove the link or name another file
work-output-not-ours = { $path } is already there and phonglab did not write it (it is not phonglab's earlier { $kind }): check and diagnose never replace a file that may be a student's; nothing was written. Name another file, or move that one away first
work-output-other-kind = { $path } is already there and is phonglab's { $found }, not its { $kind }: check and diagnose replace a file only with a new one of the same kind, so that one output never takes another's place; nothing was written. Name another file, or move that one away first
work-output-submission = { $path } is inside the checked folder and named like a student's work (.ipynb or .py): the next check would read it as a submission; name it { $suggested }, for example, or write it outside the folder
work-output-kind-report = class report (check --report)
work-output-kind-marks = marks (check --csv)
marks-column-file = file
marks-column-verdict = verdict
marks-column-first-wrong = first_wrong
marks-column-causes = causes
marks-column-cause-ids = cause_ids
marks-column-verdict-id = verdict_id
work-output-kind-chart = chart of the causes (check --report)
work-output-kind-difference = difference image (diagnose --diff)
check-chart-title = Causes in the class ({ $count } submissions)
check-verdict-word-right = right
check-verdict-word-wrong = wrong
check-scene-own = scene: the notebook's own (its typed inputs are taken as the assignment and cannot be wrong; give the assignment with --scene S.toml)
check-scene-file = scene: { $path }
check-scene-printed = scene: the worksheet's (the assignment with --scene S.toml)
check-report-no-scene = No --scene was given: each notebook's typed inputs were taken as the student's own assignment and cannot be wrong (a shininess of 0.2 instead of 0.2*128 passes). Give the assignment's scene with --scene S.toml.
check-verdict-word-unread = not read
check-verdict-word-incomplete = incomplete
check-report-unread = Not read
check-report-unchecked = incomplete (a step not printed, outputs out of order, the run stopped, too few digits to tell, or nothing compared)
cli-check = Check a student's work: a worksheet notebook with its outputs, a script's printed text, or a folder of them; each printed step against the key, the first wrong step and its likely causes. Exit code: 0 right, 1 wrong or not checked, 2 a usage or input error; for a folder, 0 once the report is written
cli-arg-check-work = The notebook (.ipynb, saved with its outputs), or a folder of them for the whole class
cli-arg-check-printed = The text a script printed, instead of a notebook (- for the standard input)
cli-arg-check-scene = The assignment's scene (TOML); default: the notebook's own (the worksheet's for printed text)
cli-arg-check-json = Write the check as JSON
cli-arg-check-report = For a folder: the class report to write (Markdown), with its bar chart beside it (.png)
cli-arg-check-csv = For a folder: the marks to write (CSV)
student-menu = Check a student's work…
student-menu-hover = A worksheet notebook saved with its outputs (.ipynb) or the text a script printed (.txt), checked against the scene shown: the student's value beside each step, the first wrong step and its likely causes; or a picture their program drew (.png, 512 x 512), diagnosed in Compare. Nothing in it is run.
student-choose-why = Choose the student's notebook (saved with its outputs, .ipynb), printed text (.txt) or picture (.png, 512 x 512).
student-choose-filter = Notebook, printed text or picture
student-check = Check
student-own-scene = { $count } of its typed inputs differ from the scene shown: it looks typed for another scene, so it is checked against the notebook's own scene (as phonglab check without --scene), and its values are not shown beside this scene's steps. Is this the right scene? To mark it against the assignment, open that scene.
student-heading = Student's work: { $file }
student-clear = Clear
student-clear-hover = Hide the student's values and the findings
student-value = yours = { $student }: { $verdict }
student-first-wrong-marker = » first wrong step
student-checked-own = Checked { $file } against its own scene (not this one): { $verdict }
student-checked = Checked { $file } against this scene: { $verdict }
student-checked-wrong = not all right; see the calculation
student-not-checked = Not checked: { $why }. The scene and the calculation are unchanged.
student-not-work = { $path } is neither a notebook (.ipynb) nor printed text (.txt)
student-ask-title = A notebook with outputs
student-ask = { $file } holds printed values. Check them against this scene, or open the notebook as the scene?
student-ask-check = Check it against this scene
student-ask-open = Open it as the scene
student-picture-heading = Student's picture: { $file }
student-picture-right = A: the right picture of this scene
student-picture-theirs = B: the student's picture
student-picture-stale = { $file } was checked against the scene as it was when it was opened; the scene shown has changed since, so that verdict is not this scene's.
student-picture-unspun = Checked against the scene's own view, as its program draws it: the turn the window's spin has given the object is left out.
student-picture-recheck = Check it against this scene
student-picture-more = The diagnosis goes on below: scroll it with the bar on its right.
student-picture-difference = Difference |A − B| × { $gain }
student-picture-difference-said = The difference (the third picture): { $said }
# fix57b
check-report-printed-twice = Steps printed more than once with different values (each printing was checked)
# fixr3
student-cause-beside = likely cause: { $words } [{ $id }] (the evidence is above the steps)
# fix60b
moodle-not-ours = { $path } was not written by phonglab, or has changed since: phonglab does not replace it. Move it away, or choose another --out.
set-not-ours = { $path } was not written by phonglab, or was edited since it wrote it: phonglab does not replace it, and wrote nothing. To write the set here, move that file away (it keeps your edits), or choose another folder.
err-category-blank = --category needs a name: it is empty or only spaces.
err-category-slash = --category cannot start or end with "/": Moodle would read the category's path wrongly.
err-category-control = --category has a control character, { $character }: a category's name is one line of text, without line breaks or tabs.
err-category-long = --category is { $length } characters long; Moodle keeps a category's name in at most { $max }.
err-worksheet-moodle = --worksheet writes exercise 0 into the sheets only; a file for Moodle takes --level or --effects.
budget-what-moodle = a file for Moodle of { $count ->
        [one] { $shown } exercise
       *[other] { $shown } exercises
    } (about { $size } on disk)
budget-what-sheets = a set of { $count ->
        [one] { $shown } exercise sheet with its key
       *[other] { $shown } exercise sheets with their keys
    } and the two PDFs (about { $size } on disk)
budget-what-wrong = a set of { $count ->
    [one] one picture
   *[other] { $count } pictures
} with one mistake each

## arg-errors

arg-error-invalid-value = { $arg } does not take { $value }: it takes { $values }.
arg-error-missing-value = { $arg } needs a value.
arg-error-out-of-range = { $arg } takes a whole number from { $low } to { $high }, not { $value }.
arg-error-not-whole = { $arg } takes a whole number, not { $value }.
arg-error-not-number = { $arg } takes a number, not { $value }.
arg-error-invalid-utf8 = One of the arguments is not text in UTF-8: only a file's or a folder's name may hold other bytes. Write the others in UTF-8.
arg-error-refused-value = { $arg } does not take { $value }: { $reason }
arg-error-unknown = There is no option { $arg }.
arg-error-did-you-mean = Did you mean { $suggestion }?
arg-error-unknown-command = There is no command { $name }.
arg-error-unknown-command-or-file = There is no command { $name }, nor a file of that name.
arg-error-missing = Missing: { $args }.
arg-error-conflict = The option { $arg } cannot be used with { $other }.
arg-error-twice = { $arg } is given twice: give it once.
arg-error-unexpected = { $arg } was not expected here: it is not an option, nor the value of one.
arg-error-more = See { $help }.
# fix57c
work-output-changed = { $path } is phonglab's earlier { $kind }, but changed since phonglab wrote it (a line added, an edit): phonglab does not erase what was added; nothing was written. Give another name (--csv marks-2.csv, --report report-2.md), or move that file away first
work-output-no-record = { $path } looks like phonglab's earlier { $kind }, but phonglab has no record of writing it here (anyone can write its first line): it is not phonglab's to replace; nothing was written. Give another name, or move it away first
work-output-records-untrusted = { $path } looks like phonglab's earlier { $kind }, but phonglab's records of what it wrote ({ $records }) are not this user's alone (another user owns them or can write there), so none is trusted; nothing was written. Give another name, or make that folder yours alone (chmod 700)
