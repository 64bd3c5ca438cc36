# As mensagens da aplicação do phonglab em português de Portugal: as da janela, as da
# linha de comandos e as dos ficheiros. As do núcleo estão em crates/phonglab-core/i18n/pt-PT.ftl.

## app

language-menu-hover = Língua, e como se escrevem os números (0,5 ou 0.5)
leave-presenting = Sair (F5)
present-hover = Letra grande; os controlos numa gaveta
controls-drawer = Gaveta dos controlos
controls-drawer-hover = Os controlos da cena, numa gaveta
controls = Controlos
calculation = Cálculo
theme-hover = Os dois temas têm alto contraste
theme-light = Tema claro
theme-dark = Tema escuro
reset-worksheet = Voltar à ficha
scene-menu = Cena
scene-menu-hover = As cenas incluídas, e a da ficha
file-menu = Ficheiro
view-menu = Ver
view-menu-hover = Painéis, janelas, o tema e a aritmética
things-to-try = Coisas a experimentar
things-to-try-hover = Experiências num clique: cada uma prepara uma cena, diz o que observar e faz uma pergunta a que o cálculo responde
things-to-try-band = Coisas a experimentar: um clique prepara cada uma
things-to-try-intro = Cliquem numa para preparar a sua cena (a atual é substituída; Ctrl+Z recupera-a).
things-to-try-look = O que observar
things-to-try-question = A pergunta
things-to-try-show = Mostrar a resposta do cálculo
things-to-try-answer = Passo { $step }: { $value }
things-to-try-no-step = O cálculo não tem o passo { $step } nesta cena.
things-to-try-own = As vossas experiências: ficheiros .toml em { $folder } (vejam a forma em assets/experiments/).
things-to-try-own-none = As vossas experiências podem ser juntadas na aplicação para computador.
experiment-no-text = não tem [text.en], [text.pt-PT] nem [text.pt-BR]
experiment-no-scene = nenhuma cena chamada { $scene } (uma cena incluída, ou um ficheiro .toml ao lado da experiência)
experiment-no-control = nenhum controlo tem como rótulo a mensagem “{ $control }” (indique o id de um rótulo, como light-z ou material-shininess)
experiment-scene-refused = a cena { $scene } não é lida: { $why }
experiment-scene-not-beside = uma experiência nomeia uma cena incluída (como worksheet-mview1) ou um ficheiro de cena ao seu lado só pelo nome (como minha-cena.toml), não uma pasta, um caminho ou uma ligação
experiment-scene-error = a cena { $scene } não carrega: { $error }
experiment-changes-refused = as suas [changes] postas sobre a cena { $scene } não dão uma cena: { $error }
experiment-folder-full = não lida: da pasta das experiências lê-se no máximo { $most } ao todo, contando as suas cenas
experiment-too-many = não lida: leem-se no máximo { $most } experiências da pasta
file-kind-experiments = ficheiros de experiências
panels-heading = Painéis e janelas
arithmetic-heading = Aritmética
file-menu-hover = O ficheiro da cena, exportar, desfazer e refazer
redbook-teapots = Bules do Red Book
compare = Comparar
compare-hover = Fixe a cena como A: mude o que quiser e veja A e B lado a lado
director = Vista do realizador
director-hover = A cena vista de fora: o olho e o seu tronco de visão, as luzes com os seus anéis e cones, o vértice do cálculo com N, L, V e H, no espaço do objeto, do mundo ou do olho
director-space = Espaço
director-eye = olho
director-vertex = vértice
director-light = luz { $n }
director-legend = no vértice, todos do mesmo comprimento; quadrado azul: o plano próximo (o viewport); quadrado verde: a superfície no vértice. Arraste uma luz ou o olho para o mover; arraste noutro sítio para rodar; role para aproximar.
director-naive-normal = A ponteado, em azul-claro: M n, a normal transformada como um ponto, a { $degrees }° da normal verdadeira (M^-1)^T n, que continua perpendicular à superfície.
director-rules-naive = As regras desta cena (as da ficha) iluminam o vértice com M n; as do OpenGL usam (M^-1)^T n.
director-ring = Luz { $n }: 1/at, o fator de atenuação, cai para { $percent } % à distância { $distance } (um anel).
wrong-title = O que está errado nesta imagem?
wrong-intro = Cada ficha mostra uma esfera desenhada corretamente e desenhada com um erro. Escolha o erro; a chave explica-o com os números da sonda de píxel.
wrong-sheet-title = O que está errado nesta imagem? ({ $number })
wrong-drawn-right = Desenhada corretamente
wrong-drawn-wrong = Desenhada com um erro
wrong-question = Que erro produz a imagem da direita? Assinale-o e diga o que na imagem o mostra.

## presets

preset-group-worksheet = A ficha
preset-group-phong-demo = A demo de Phong
preset-group-more = Mais cenas
preset-worksheet = Ficha, { $modelview }
preset-phong-demo = Demo de Phong
preset-spotlight = Foco
preset-three-lights = Três luzes
preset-of-set-color = ofSetColor com iluminação
preset-gouraud-misses-the-highlight = Porque o Gouraud falha o brilho

## controls

controls-rules = Regras
controls-lights = Luzes
controls-material = Material
controls-light-model = Modelo de iluminação
controls-vertex = Vértice
controls-camera = Câmara (modelview)
rule-set = Regras de cálculo
specular-model = Modelo especular
rules-opengl-summary = Emissão + ambiente da cena + as componentes ambiente, difusa e especular de cada luz (OpenGL 2.1, 2.14.1).
rules-worksheet-summary = A ficha de trabalho: sem ambiente da cena nem emissão; difusa 0 além de 90 graus, especular 0 além de 90 graus.
rules-demo-summary = O shader da demo de Phong: sem ambiente da cena nem emissão, pow(max(R.V, 0), e) sem outra condição.
placement-eye = o olho (move-se com a câmara)
placement-world = o mundo
placement-object = o objeto (roda com ele)
placement-matrix = uma matriz escrita
add-light = Juntar luz
remove-light = Remover luz
lights-of-max = { $count } de { $max }
no-lights = Sem luzes: restam apenas a emissão e o ambiente da cena.
directional = Direcional (w = 0)
light-x = Luz x
light-y = Luz y
light-z = Luz z
light-fixed-to = Luz presa a
attenuation-positional-only = A atenuação só vale para luz pontual ou foco.
spotlight = Foco
spotlight-hover = Um foco novo aponta para o objeto da vista
material-custom = personalizado
material-preset = Material pré-definido
back-preset = Verso pré-definido
back-ambient = Verso: ambiente
back-diffuse = Verso: difusa
back-specular = Verso: especular
back-emission = Verso: emissão
back-shininess = Verso: brilho (ns)
separate-back-material = Material próprio para o verso
color-material = Cor do material (GL_COLOR_MATERIAL)
color-material-hover = As cores do material que acompanha seguem a cor corrente (glColor), como o ofSetColor do openFrameworks faz sob ofEnableLighting
color-material-mode = Acompanha
color-material-face = Faces
color-material-color = Cor corrente (glColor)
color-material-tracked = O GL_COLOR_MATERIAL faz desta a cor corrente: o que aqui está volta quando for desligado
separate-specular = Cor especular separada
normals-as-is = como transformadas
normals = Normais
normalise-normal = Normalizar a normal
camera-eye = Olho
camera-centre = Centro
camera-up = Cima
window-width = Largura da janela
window-height = Altura da janela
of-eye-distance = Distância do olho (H/2)/tan(30 graus) = { $distance }
object-placement = Posição do objeto (do objeto para o mundo)
object-matrix = Objeto
matrix-column = coluna { $column }
matrix-row = { $name } linha { $row }
matrix-cell = { $name } linha { $row } coluna { $column }
mview1-what = a câmara do openFrameworks, translação em z de −665,108
mview2-what = uma rotação em torno de x, tal como impressa (uma entrada com menos um algarismo, −0,85749)
mview34-what = construída com 15/17 e 8/17, tal como a ficha a imprime
mview5-what = uma rotação 3-4-5 em torno de x e translação em z de −960

## result

unclamped = sem limite
unclamped-hover = A cor primária tal como a equação a dá.
clamped = limitada a [0, 1]
clamped-hover = Primária + secundária rgb, limitada a [0, 1]: o que um fragmento recebe.
dark-vertex = um vértice escuro: { $percent } % do brilho do branco
dark-vertex-angle = um vértice escuro: { $percent } % do brilho do branco; a luz chega-lhe a { $angle }°
dark-vertex-short = vértice escuro
large-value-hover = A cor desenhada (limitada a [0, 1]), r g b com duas casas decimais
secondary = secundária
secondary-hover = A cor secundária (especular).
vertex-colour = Cor do vértice
front-face = Face da frente
back-face = Face de trás
colour-hidden = Escondida enquanto o teste está aberto: é a última resposta do teste, I.
colour-hidden-teacher = O professor pode mostrá-la com "Mostrar as respostas" no teste.
refused-kept = Recusado: { $error }. A cena mantém o último valor válido.
history-reset = voltar à ficha
reset-done = De volta à ficha (mview5).
history-open = abrir { $what }
loaded = Aberto: «{ $what }»
undid = Desfeito: { $what }.
redid = Refeito: { $what }.
history-no-change = sem alteração
history-and-more = { $field } e mais { $count }
history-light-added = luz { $index } acrescentada
history-light-removed = luz { $index } removida
history-none = (nenhum)
history-on = ligado
history-off = desligado
# A changed field of the scene, as the undo history names it. $field is the scene file's
# path with dots as dashes and a light's number taken out (light-position of light $index).
history-field = { $field ->
    [name] nome da cena
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
    [light-position] luz { $index }: posição
    [light-ambient] luz { $index }: ambiente
    [light-diffuse] luz { $index }: difusa
    [light-specular] luz { $index }: especular
    [light-spot_direction] luz { $index }: direção do foco
    [light-spot_cutoff] luz { $index }: abertura do foco
    [light-spot_exponent] luz { $index }: expoente do foco
    [light-attenuation] luz { $index }: coeficientes de atenuação (k0, k1, k2)
    [light-placement] luz { $index }: presa a
    [vertex-position] { quantity-vertex-position }
    [vertex-normal] { quantity-vertex-normal }
    [view-object] objeto
    [view-obj] { mesh-file }
    [view-shading] sombreamento
    [view-sphere_slices] { sphere-slices }
    [view-sphere_stacks] { sphere-stacks }
    [view-teapot_grid] { teapot-grid }
    [view-cylinder_slices] { cylinder-slices }
    [view-cylinder_stacks] { cylinder-stacks }
    [view-cylinder_caps] tampas do cilindro
    [view-cylinder_centered] cilindro centrado
    [view-demo_normals] { demo-normals }
    [view-auto_rotate] { auto-rotate }
    [view-spin_degrees] rotação
    [view-framing] enquadramento
    [view-lighting_space] espaço da iluminação
    [view-flat_normal] { flat-derivatives }
    [view-phong_renormalize] { phong-renormalises }
    [view-background] fundo
    [view-camera] câmara da vista
   *[other] a cena
}
not-whole = { $text } não é um número inteiro
outside-range = { $text } está fora de { $min } a { $max }
numbers-type-one = { $count } números: escreva um
numbers-type-row = { $count } números: escreva um, ou todos os { $fields } da linha
refused-esc = { $why } (Esc: volta a { $value })

## help

help-help = mostrar ou esconder esta ajuda
help-present = apresentar: letra grande, os controlos numa gaveta (F5 outra vez para sair)
help-walk-steps = percorrer os passos do cálculo, um a um (quando nenhum campo tem o teclado)
help-zoom = ampliar, reduzir, voltar a 100 % a janela toda
help-things-to-try = Coisas a experimentar (barra de cima): experiências num clique, cada uma com uma pergunta a que o cálculo responde.
help-local-viewer = ligar ou desligar o observador local
help-next-material = material clássico seguinte
help-previous-material = material clássico anterior
help-next-modelview = modelview seguinte da ficha (mview1..5)
help-specular-model = modelo especular seguinte (Blinn-Phong, Phong, Blinn-Phong normalizado)
help-next-rules = regras seguintes (OpenGL, ficha, demo de Phong)
help-next-normals = modo seguinte das normais (como estão, normalizar, reescalar)
help-two-sided = iluminação das duas faces ligada/desligada
help-precision = cálculo em f32 / f64
help-reset = voltar à ficha
help-open = abrir o ficheiro de cena no caminho escrito
help-save = guardar a cena no caminho escrito
help-quit = sair (a sessão é guardada)
help-undo = desfazer a última alteração da cena
help-redo = refazer
help-sphere = vista sombreada: esfera (como a demo)
help-teapot = vista sombreada: bule
help-cylinder = vista sombreada: cilindro
help-gouraud = sombreamento de Gouraud (como a demo)
help-phong = sombreamento de Phong
help-flat = sombreamento plano (Flat)
help-auto-rotate = rodar a vista sombreada sozinha
help-drop = Largue um ficheiro de cena (.toml) na janela para o abrir.
help-drag = Arraste o gráfico dos vetores ou a vista sombreada para os rodar; use a roda na vista sombreada para ampliar; clique na superfície para explicar esse vértice.
help-numbers = Um campo numérico aceita ponto ou vírgula decimal e lê o que foi escrito quando se sai dele (Enter, Tab, um clique noutro sítio); um valor recusado fica a vermelho com a razão até ser corrigido ou até Esc repor o valor.
help-undo-keys = Ctrl+Z desfaz qualquer alteração da cena. As teclas sem Ctrl não fazem nada enquanto um campo de texto tem o teclado, nem no teste.
help-demo-title = A cena da demo de Phong: as escolhas da demo e as do OpenGL
help-demo-space = Da demo: iluminação no espaço do objeto, luz e olho em (-4, 0, -8), por isso a luz roda com o objeto. Do OpenGL: iluminação no espaço do olho, depois da modelview (interruptor: luz presa ao mundo).
help-demo-normals = Da demo: cada normal é normalize(posição). Do OpenGL: as normais da superfície (interruptor: as normais verdadeiras da superfície).
help-demo-specular = Da demo: R = 2 max(N.L, 0) N - L e pow(max(V.R, 0), 100), vezes o vermelho do objeto, por isso o brilho é vermelho. Do OpenGL: o n.H de Blinn-Phong e a cor especular da luz vezes a do material (interruptor: brilho da cor da luz).
help-demo-pipeline = Da demo: sem projeção (a imagem é o espaço de recorte), Phong sem renormalizar, Flat a partir de dFdx/dFdy por fragmento, cores interpoladas sem limite. Em Pipeline, a vista sombreada oferece as escolhas do OpenGL.

## quiz

quiz-input-yours = o seu { $name } = { $value }
quiz-input-key = o { $name } da chave (ainda sem resposta)
quiz-the-givens = os dados
quiz-right = ✔ certo
quiz-right-given = ✔ certo, dado o seu { $yours }
quiz-close-key = ≈ perto: a { $percent } % da chave; dê { $digits } algarismos significativos
quiz-close-yours = ≈ perto: a { $percent } % do que as suas respostas anteriores dão; dê { $digits } algarismos significativos
quiz-wrong = ✖ errado: { $formula }, com { $inputs }
quiz-level = Nível
quiz-levels = 1 direcional, 2 pontual com atenuação, 3 focos, 4 duas faces com várias luzes
quiz-this-scene = Testar esta cena
quiz-this-scene-hover = Recomeçar com a cena mostrada, todos os valores escondidos
quiz-new-exercise = Novo exercício
quiz-new-exercise-hover = Uma cena nova deste nível, filtrada como o phonglab exercise filtra
quiz-reveal-all = Mostrar todas as respostas
quiz-reveal-all-hover = Mostrar o valor da chave em cada passo: nenhum conta então como certo
quiz-clear = Limpar respostas
quiz-clear-hover = Recomeçar este teste sem respostas
quiz-show-answers = Mostrar as respostas (professor)
quiz-show-answers-hover = A cor do vértice, os ângulos do gráfico e a chave de cada passo
quiz-nothing-open = Abra um exercício (o phonglab exercise escreve-os) ou qualquer cena e carregue em "Testar esta cena", ou carregue em Novo exercício.
quiz-instructions = { $scene }: escreva o valor de cada passo e prima Enter. Certo: a menos de { $percent } % do valor (ou { $absolute } perto de 0). Ponto ou vírgula; um vetor como 0,5; 0,3; 0,1.
quiz-score = Pontuação: { $right } de { $all } ({ $answered ->
    [one] 1 respondido
   *[other] { $answered } respondidos
}{ $shown ->
    [0] {""}
    [one] , 1 resposta mostrada
   *[other] , { $shown } respostas mostradas
})
quiz-your-value = o seu valor
quiz-reveal = Mostrar a resposta
quiz-reveal-hover = Mostrar o valor da chave neste passo: deixa então de contar como certo
quiz-not-numbers = não se lê como números: { $error }
quiz-key = chave: { $name } = { $value }

## calculation

plan-heading = Plano especializado: { $computed ->
        [one] 1 efeito calculado
       *[other] { $computed } efeitos calculados
    }, { $skipped ->
        [one] 1 saltado
       *[other] { $skipped } saltados
    }
plan-light = luz { $index }:{" "}
plan-computed = calculado  { $what }
plan-skipped = saltado   { $what }
plan-program = O programa, { $stages } etapas por bloco de vértices:
worked-calculation = Cálculo passo a passo
copy-markdown = Copiar como Markdown
copy-markdown-hover = Copia todos os passos como uma tabela Markdown.
side = Face:
not-applicable = não se aplica
skipped-by-specialised = saltado pelo avaliador especializado: { $why }
plot-view = Vista:
plot-legend-halfway = vetor médio
plot-view-hover = Ver o plano { $plane }

## view

pipeline = Pipeline: a do OpenGL ou a da demo
picture = Imagem
phong-renormalises = Phong renormaliza N
phong-renormalises-hover = Os shaders do OpenGL normalizam a normal interpolada; o da demo não
flat-derivatives = Flat a partir de dFdx/dFdy
flat-derivatives-hover = O Flat da demo: cada fragmento iluminado com cross(dFdy(p), dFdx(p)); senão, uma cor por face
correct-the-demo = Corrigir a demo:
why-demo-differs = Porque é que a demo difere
why-demo-differs-intro = Cada interruptor ligado corrige a demo numa segunda imagem, à direita da sua.
sphere-slices = Fatias da esfera
sphere-stacks = Camadas da esfera
teapot-grid = Grelha do bule
cylinder-slices = Fatias do cilindro
cylinder-stacks = Camadas do cilindro
caps = Tampas
mesh-triangles =
    { $count ->
        [one] 1 triângulo
       *[other] { $count } triângulos
    }: { $notes }
key-hint = tecla { $key }
mesh-tip = { $path } (abra outra em Opções da vista, ou largue um ficheiro .obj)
close-mesh = Fechar a sua malha
close-mesh-hover = Fechar a sua malha: a barra de cima deixa de a oferecer (fica no seu ficheiro; mudar de cena mantém-na até lá)
auto-rotate = Rodar sozinho
auto-rotate-hover = 0,5 graus por imagem, como a demo (tecla A)
demo-normals = Normais da demo
demo-normals-hover = normalize(posição), como a demo: erradas para o bule e o cilindro
heat-map = Mapa de calor do erro
heat-map-hover = Ao lado da vista: a distância de cada píxel ao Phong por píxel em f64 numa malha muito fina
view-options = Opções da vista
view-options-hover = O renderizador, a resolução da malha, as escolhas do pipeline, um ficheiro de malha
mesh-file = Ficheiro da malha (.obj):
mesh-file-hint = pasta/da/malha.obj
show-mesh = Mostrar a malha
show-mesh-hover = Sombrear este ficheiro OBJ na vista (Enter no campo)
shaded-cannot-render = A vista sombreada não consegue desenhar esta cena
corrected-cannot-render = A vista corrigida não consegue desenhar
the-demos-own = {" "}(a da própria demo)
picture-hover = Arraste para rodar, use a roda para ampliar, clique na superfície para que esse vértice seja o do cálculo
corrected = Corrigida: { $fixes }
corrected-short = Corrigida ({ $count } de { $all })
picked-vertex = Vértice { $index } de { $object }: o cálculo passa a usá-lo, tal como a vista sombreada o ilumina.
light-behind = luz { $index } (atrás da câmara)
light-name = luz { $index }
light-drag = Luz { $index }: arraste para a mover
arrows-faded = Esbatida, ponta aberta: o vetor aponta para longe de ti, ou para dentro da superfície.
renderer = Desenho
renderer-hover = O desenho no CPU é a referência; a GPU corre o WGSL gerado para a cena (janela Shader)
renderer-auto = Automático (GPU, se for real)
renderer-cpu = CPU (a referência)
renderer-gpu = GPU (mesmo por software)
drawn-gpu = Desenhado na GPU ({ $adapter }) pelo WGSL gerado para a cena.
drawn-cpu = Desenhado pelo CPU: { $why }.
gpu-none = não há GPU aqui
caption-gpu = na GPU ({ $adapter })
caption-cpu = { $ms } ms por imagem no CPU
caption-cpu-relit = só iluminada de novo, nada do que se desenha se moveu: { $ms } ms por imagem no CPU
caption-cpu-coarse = uma cópia com { $triangles } dos { $all } triângulos enquanto a câmara roda: { $ms } ms por imagem no CPU
caption-cpu-coarse-spin = uma cópia com { $triangles } dos { $all } triângulos enquanto o objeto gira: { $ms } ms por imagem no CPU
cpu-flat = o sombreamento Flat é desenhado no CPU (o gerador escreve Gouraud e Phong)
cpu-approximate-pow = uma potência aproximada estuda-se no CPU (a pow da GPU é a sua)
cpu-no-adapter = não há adaptador wgpu aqui (sem ecrã, ou outro backend)
cpu-chosen = o desenho no CPU está escolhido em Opções da vista
cpu-software-adapter = o adaptador ({ $adapter }) é por software, não mais rápido do que o CPU

## files

not-opened-worksheet = Não aberto: { $why }. Em vez disso, mostra-se a ficha.
not-opened = Não aberto: { $why }. A cena atual não mudou.
mesh-summary =
    { $triangles ->
        [one] 1 triângulo
       *[other] { $triangles } triângulos
    }, { $vertices } vértices; { $notes }
opened-mesh = Malha aberta: { $path }: { $what }.
not-text = { $path } não é um ficheiro de texto
saved = Guardado: { $path }.
not-saved = Não guardado: { $error }.
scene-file = Ficheiro de cena:
scene-file-hint = caminho/para/cena.toml
open = Abrir
open-hover = Abrir o ficheiro de cena neste caminho (Ctrl+O)
save = Guardar
save-hover = Guardar a cena neste caminho (Ctrl+S)
open-dialog = Abrir…
open-dialog-hover = Escolher um ficheiro de cena na janela de ficheiros do sistema
dialog-no-session-bus = A janela de ficheiros do sistema não pode abrir aqui (não há bus de sessão para o seu portal): escolha o ficheiro no seletor do phonglab.
dialog-did-not-open = A janela de ficheiros do sistema não abriu (nenhum portal respondeu): escolha o ficheiro no seletor do phonglab.
dialog-in-app = Escolha o ficheiro aqui.
chooser-title = Escolher um ficheiro
chooser-folder = Pasta:
chooser-up = Subir
chooser-name = Nome do ficheiro:
chooser-cancel = Cancelar
chooser-empty = (não há aqui pastas nem ficheiros deste tipo)
save-as = Guardar como…
save-as-hover = Escolher onde guardar na janela de ficheiros do sistema
drop-to-open = Largue um ficheiro de cena (.toml) ou uma malha (.obj) para o abrir
cannot-read = não é possível ler { $path }: { $error }
dropped-several = {" "}(foram largados { $count } ficheiros; só se abre o primeiro.)
type-path-first = Escreva primeiro o caminho do ficheiro de cena.

## browser

browser-no-storage = este navegador não guarda dados locais para a página
browser-storage-refused = o navegador recusou guardar a sessão ({ $error })
browser-download-failed = o navegador não conseguiu oferecer a transferência ({ $error })
open-browser-hover = Escolher neste computador um ficheiro de cena (.toml), uma malha (.obj) ou um caderno ou programa da ficha (.ipynb, .py)
save-download-hover = Transferir a cena como ficheiro (.toml)
downloaded = { $name } oferecido para transferir.

## export

export = Exportar
export-png = Vista sombreada em PNG ({ $size }×{ $size })
export-png-hover = A vista sombreada desenhada no CPU, como o phonglab render a desenha
export-exercises = Fichas de exercícios
export-seed = Semente
export-count = Exercícios
export-level = Nível
export-levels = 1 direcional, 2 pontual com atenuação, 3 focos, 4 duas faces com várias luzes
export-exercises-save = Guardar as fichas (.zip)
export-exercises-hover = As fichas e as respostas, em Markdown, ficheiros de cena e os dois PDF (sheets.pdf para distribuir, keys.pdf para o professor), nesta língua
exported = Guardado { $what }: { $at }
not-exported = { $what } não foi guardado: { $error }

## student-code

err-export-folder = openframeworks escreve três ficheiros: indique uma pasta com -o (vão para a sua src/)
export-written = escrito: { $path }
bench-mesh-written = malha escrita: { $path } ({ $triangles } triângulos, { $vertices } vértices)
bench-coarse-made = { $object }: a cópia grosseira tem { $triangles } dos { $all } triângulos, feita em { $ms } ms
import-written = cena escrita: { $path } ({ $lights })
budget-over = { $what } precisa de cerca de { $needed }, mais do que o orçamento de memória de { $budget } ({ $from }); --memory-budget TAMANHO aumenta-o: esta execução precisa de --memory-budget { $suggest } ou mais
budget-from-option = como pede --memory-budget
budget-from-option-bare = como pede --memory-budget { $number }: um tamanho sem unidade conta bytes; { $number } MiB é --memory-budget { $number }M
budget-from-system = metade da memória disponível
budget-from-limit = metade do espaço de endereçamento que resta sob o limite deste processo, ulimit -v
budget-over-limit = --memory-budget { $budget } é mais do que este processo ainda pode ocupar sob o seu limite, ulimit -v (restam { $room }): uma execução que o ultrapasse pararia a meio. Baixe --memory-budget, ou aumente o limite (ulimit -v)
budget-size-negative = { $value }: um tamanho não pode ser negativo; escreva um tamanho como 512M, 8G ou 1,5G
budget-size-refused = { $value }: escreva um tamanho como 512M, 8G ou 1,5G
budget-what-render = uma imagem de { $width } x { $height } com { $count ->
        [one] um triângulo
       *[other] { $triangles } triângulos
    }
budget-what-window = a janela a { $width } x { $height } píxeis
budget-what-diagnose = comparar uma imagem de { $size } x { $size } com { $count } desenhos, um de cada vez,
budget-what-check = verificar { $count ->
    [one] um trabalho de { $largest }
   *[other] { $count } trabalhos, o maior com { $largest },
}
budget-what-cost = o estudo de { $count ->
    [one] um objeto
   *[other] { $count } objetos
} a { $size } x { $size } píxeis
budget-what-eval = iluminar { $count ->
    [one] um caso de { $largest }
   *[other] { $count } casos, um de cada vez, o maior com { $largest }
} de JSON
cli-export = Escrever uma cena como o código do próprio aluno: o caderno da ficha, um programa PyOpenGL, uma app openFrameworks, ou o GLSL
cli-import = Ler um caderno (.ipynb) ou programa em Python (.py) no estilo da ficha para um ficheiro de cena
cli-arg-export-scene = Um ficheiro de cena (TOML); por omissão: a cena da ficha
cli-arg-export-to = O que escrever
cli-arg-export-output = Onde: um ficheiro (uma pasta para openframeworks: os ficheiros vão para a sua src/); sem isto o texto vai para a saída padrão
cli-arg-import-file = Um caderno (.ipynb) ou programa em Python (.py) no estilo da ficha
cli-arg-import-output = O ficheiro de cena a escrever (TOML)
cli-value-notebook = o caderno Jupyter da ficha (.ipynb), com os valores desta cena
cli-value-pyopengl = um programa PyOpenGL + GLUT no estilo da demo de Phong (.py)
cli-value-openframeworks = ofApp.h, ofApp.cpp e main.cpp para openFrameworks 0.12 (uma pasta)
cli-value-glsl = o GLSL que o `phonglab shader` imprime
export-code = O seu próprio código
export-copy = Copiar
export-copy-hover = Copiar para a área de transferência (o caderno como um só programa, os ficheiros do openFrameworks um após o outro)
export-save = Guardar…
export-save-hover = Guardar como ficheiro (openFrameworks: um zip da pasta src/ do projeto)
export-copied = Copiado: { $what }
export-nothing = nada para escrever
export-import-hint = Para o caminho inverso, abra ou largue um caderno (.ipynb) ou programa (.py) da ficha: os seus valores passam a ser a cena.
imported = Aberto { $path } como cena (as regras da ficha, salvo se ele disser outras).{ $notices }

## plots

plot-drag = Arraste para rodar (guinada { $yaw }°, inclinação { $pitch }°)
lobe-no-light = Nenhuma luz com L definido neste vértice: nada a desenhar.
lobe-axis = φ, graus a partir de N
lobe-luminance = { $name } = { $value } (a luminância de { $colour })
lobe-caption = Luz { $light }: θ = { $theta }°, n = { $n }, { $kd }, { $ks }; o V do vértice em φ = { $phi }°
lobe-diffuse = difusa kd cos θ
lobe-normalised = Blinn-Phong × (n+8)/8π
lobe-vertex-v = o V do vértice

## compare

compare-same = A e B são a mesma cena: mude qualquer coisa e B acompanha
compare-one = B: { $setting } { $b }; A: { $a }
compare-several = A e B diferem em { $names }
compare-many = A e B diferem em { $count } parâmetros
compare-view = vista sombreada de { $which }, { $ms } ms
compare-cannot-render = a vista de { $which } não consegue desenhar: { $error }
compare-pin-again = Fixar de novo a cena atual como A
compare-pin = Fixar a cena atual como A
compare-pinned = Fixada como A: agora mude qualquer coisa e B acompanha.
compare-close = Fechar a comparação
compare-difference = Diferença |A − B|
compare-difference-hover = Uma terceira imagem: quanto diferem os píxeis de A e de B, ampliado
compare-difference-view = |A − B| × { $gain }
compare-difference-legend = A diferença de cada canal, vezes { $gain }: um canal fica no máximo a partir de { $full }/255 (branco onde os três ficam, preto onde A e B coincidem). { $percent } % dos píxeis do objeto diferem mais de { $visible }/255; a maior diferença é { $largest }/255.
compare-step-1 = 1. Fixe a cena atual como A (o botão acima).
compare-step-2 = 2. Mude qualquer coisa: o sombreamento, f32 ou f64, o material, uma luz.
compare-step-3 = 3. A e B aparecem lado a lado, com os passos que diferem primeiro.
compare-a-fails = A não pode ser calculada: { $error }
compare-differing = { $differing ->
    [one] 1 de { $all } passos difere: vem primeiro, destacado.
   *[other] { $differing } de { $all } passos diferem: vêm primeiro, destacados.
}
compare-none-differ = Nada difere: A e B dão o mesmo valor em cada um dos { $all } passos.
copy = Copiar
copy-program-hover = Copiar o programa para a área de transferência
shader-stages-phong = Sombreamento de Phong (por fragmento): só as etapas de que esta cena precisa
shader-stages-vertex = Sombreamento por vértice: só as etapas de que esta cena precisa
shader-last-change = A última alteração juntou { $added ->
        [one] 1 linha (destacada)
       *[other] { $added } linhas (destacadas)
    } e removeu { $removed }.
shader-removed = Removido pela última alteração:
session-other-window = Outra janela do phonglab está aberta nesta sessão ({ $dir }): esta janela mostra a última cena guardada mas não guardará a sua sessão. Use Guardar para manter o seu trabalho num ficheiro.
session-folder-unusable = A pasta da sessão { $dir } não pode ser usada ({ $error }): esta janela não guardará a sua sessão.
session-file-is-folder = O ficheiro da sessão { $path } é uma pasta, por isso a última sessão não pode ser lida e esta janela não guardará a sua sessão. Remova essa pasta ou mude-lhe o nome.
session-unreadable-kept = A sessão guardada não pôde ser lida ({ $why }); começa-se pela ficha. O ficheiro fica guardado como { $kept }.
session-unreadable-not-kept = A sessão guardada { $path } não pôde ser lida ({ $why }) nem posta de lado ({ $error }); fica como está, sem nunca ser escrita por cima: começa-se pela ficha, e esta janela guarda a sua sessão em { $instead }.
session-unreadable = A sessão guardada não pôde ser lida ({ $why }).
session-not-a-file = não é um ficheiro normal: um pipe, um dispositivo ou um socket
session-too-large = tem { $size }, e uma sessão tem no máximo { $cap }
session-scene-kept = A cena fica guardada em { $path }.
session-scene-not-kept = Não pôde ser guardada ({ $error }).
session-no-folder = Não há pasta onde a guardar.
session-scene-not-restored = A cena da última sessão não pôde ser reposta ({ $error }); começa-se pela ficha. { $kept }

## sheets

sheet-scene-file = Ficheiro de cena: `{ $file }`.
key-title = Respostas: { $name }
key-intro = Tal como `phonglab explain { $file }` as imprime (8 algarismos significativos).
worked-calculation-of = Cálculo passo a passo: { $name }
exercise-zero-title = Exercício 0: a ficha
exercise-zero-name = a ficha
exercise-zero-intro = A própria cena da ficha (bronze, a luz em (0, 0, 90), o vértice (-512, -384, 0) com normal (0, 0, 1)) com cada uma das suas cinco modelviews, `mview1` a `mview5`. Calcule todos os passos para cada uma.
answers = respostas
index-directional-only = só uma luz direcional
index-title = Exercícios, semente { $seed }
index-intro = Efeitos: { $effects }. Regras: { $rules }. Cada ficha tem o seu ficheiro de cena (abra-o no phonglab) e as suas respostas.
index-printable = Para imprimir: [sheets.pdf](sheets.pdf) (para distribuir: impresso frente e verso, cada exercício fica na sua própria folha) e [keys.pdf](keys.pdf) (as respostas, para o professor).
index-printable-one-sided = Para imprimir: [sheets.pdf](sheets.pdf) (para distribuir: uma página por exercício, por isso impresso só de um lado cada exercício fica na sua própria folha) e [keys.pdf](keys.pdf) (as respostas, para o professor).

## pdf

sheet-class = Turma
sheet-name = Nome
sheet-date = Data
pdf-page = página { $page } de { $pages }
pdf-blank-page = Esta página foi deixada em branco propositadamente.

## cli

exercises-written =
    { $count ->
        [one] 1 exercício
       *[other] { $count } exercícios
    } em { $out }{ $redraws ->
        [0] {""}
        [one] {" "}(1 sorteio rejeitado: faltava-lhe um efeito pedido ou caía num caso-limite)
       *[other] {" "}({ $redraws } sorteios rejeitados: faltava-lhes um efeito pedido ou caíam num caso-limite)
    }

## moodle-exam

exam-key-heading = Cada valor exato e arredondado
exam-sheet-name = exercício de exame { $number }
moodle-category-exercise = exercício { $number }
moodle-question-name = { $exercise }, variante { $variant }: chave exercise-{ $sheet }-key.md de { $command }
moodle-category-default = phonglab
moodle-written = { $file } em { $out }: { $questions ->
    [one] uma pergunta
   *[other] { $questions } perguntas
} { $categories ->
    [one] numa categoria
   *[other] em { $categories } categorias
}. No Moodle: Banco de questões → Importar → { $format }.
moodle-format-xml = Formato Moodle XML
moodle-format-gift = Formato GIFT
exam-key-exact = exato
exam-key-rounded = arredondado a quatro algarismos significativos
err-exam-level-5 = --exam gera exercícios dos níveis 1 a 4; o nível 5 tem imagens, não números.
err-moodle-only = --variants e --category servem para um ficheiro para o Moodle (--format moodle-xml ou gift); as fichas usam --count.
err-level-5-variants = --variants é para os níveis 1 a 4: o nível 5 tem uma imagem por erro, sete ao todo, nenhuma desenhada duas vezes; use --count (1 a 7).
level-5-count = O nível 5 tem { $all } erros, uma pergunta cada: { $all } perguntas, não { $count }.
wrong-written = { $count ->
    [one] 1 imagem com um erro, com a sua chave,
   *[other] { $count } imagens com um erro cada, com as chaves,
} em { $out }
wrong-quiz-hover = Uma esfera desenhada corretamente e desenhada com um erro: escolha o erro
wrong-check = Verificar
wrong-right-answer = Certo.
wrong-wrong-answer = Não é esse. A chave:
wrong-back = Voltar ao cálculo
share-summary = uma ligação de { $length } caracteres: a cena vai na própria ligação
share-window = Partilhar esta cena
share-menu = Partilhar ligação…
share-menu-hover = A cena como ligação e código QR, para a turma abrir num navegador (nada fica guardado num servidor: a cena vai na própria ligação)
share-page = Página que a ligação abre
share-page-hover = Onde a versão para o navegador está publicada (vazio: esta página, num navegador; senão, o sítio do projeto)
share-in-language = Abrir em { $lang }
share-presenting = Abrir em modo de apresentação
share-channel = Abrir a mostrar { $term }
share-length = { $length } caracteres: a cena vai na própria ligação
share-copy = Copiar ligação
share-copy-hover = Põe a ligação na área de transferência, para colar no chat ou na página da turma
share-copied = Ligação copiada ({ $length } caracteres): cole-a para a turma, ou deixe-a ler o código.
share-qr = Código QR da ligação
share-qr-too-long = A ligação é longa demais para um código QR; copie-a.
err-share-lang = língua desconhecida { $value }: en, pt-PT ou pt-BR
share-opened = a ligação partilhada ({ $name })
share-not-opened = A ligação partilhada não foi aberta: { $why }. Esta é a cena que tinha.
share-needs-mesh = A cena da ligação mostra a malha { $name }, que uma ligação não leva: abra ou largue { $name } para a ver (até lá, a esfera toma o seu lugar).
mesh-not-kept = (Não fica guardada para quando a página for recarregada: { $why }; abra-a de novo depois disso.)
mesh-too-large-to-keep = comprimida, tem { $packed } caracteres, e a página guarda no máximo { $most }
mesh-not-restored = Não foi possível ler de novo a malha { $name } que esta página guardou ({ $why }): abra-a outra vez.
quiz = Teste
quiz-hover = Cada valor do cálculo atrás de um campo: escreva-os passo a passo
shader-hover = O programa GLSL ou WGSL em que esta cena se compila: só as etapas de que precisa
precision = Precisão:
f32-hover = Calcular em precisão simples, como o OpenGL
f64-hover = Calcular em precisão dupla
cost-of-accuracy = Custo da exatidão
cost-hover = O que cada sombreamento, tesselação e aproximação custa em tempo e em erro
help-button = Ajuda (F1)
undo-what = Desfazer: { $what } (Ctrl+Z)
redo-what = Refazer: { $what } (Ctrl+Shift+Z, Ctrl+Y)
undo-button = ⟲ Desfazer
redo-button = ⟳ Refazer
nothing-to-undo = Nada a desfazer
nothing-to-redo = Nada a refazer
could-not-evaluate = Não foi possível calcular a cena ({ $error }); de volta à ficha.
keyboard-shortcuts = Atalhos de teclado
vectors-at-vertex = Vetores no vértice
reflection-lobe = Lóbulo de reflexão
session-not-saved = Não foi possível guardar a sessão: { $error }.
no-session-folder = Não há pasta onde guardar a sessão (HOME não está definida): esta janela não guardará a sua sessão.

## cli-out

render-summary = { $path }: { $size } px, { $triangles } triângulos, { $covered } % coberto, { $evaluations } cálculos de iluminação, { $ms } ms
render-channel-summary = canal { $channel } em { $map }: de { $low } a { $high }
probe-uncovered = O píxel ({ $x }, { $y }) não mostra nenhuma superfície (é o fundo).
err-probe-at = esperava o píxel como X,Y (dois números inteiros), recebi { $value }
err-probe-outside = o píxel ({ $x }, { $y }) está fora da imagem de { $size }x{ $size }
probe = Sonda
probe-hover = Porque é que este píxel tem esta cor? Aponte para a imagem; clique para fixar um píxel
probe-window = Sonda de píxel
probe-follows = Segue o ponteiro sobre a imagem; clique para fixar um píxel.
probe-pinned = Fixada no píxel clicado.
probe-unpin = Voltar a seguir o ponteiro
probe-hover-the-picture = Aponte para a imagem sombreada.
probe-open-vertex = Abrir o cálculo do vértice { $vertex }
channel-show = Mostrar
channel-picture = A imagem
channel-hover = Um termo da equação de iluminação em cada píxel, em falsa cor (viridis), com a sua escala
channel-caption = termo { $channel }
channel-legend-normal = A normal como cor: x a vermelho, y a verde, z a azul, de -1 (escuro) a 1 (claro)
channel-legend-luminance = { $channel }: a luminância (Rec. 709) de um termo de cor, antes de limitar
channel-legend-range = { $what }, de { $low } a { $high }
channel-legend-attenuation = 1/at: o fator pelo qual os termos desta luz são multiplicados (at = k0 + k1 d + k2 d², o da ficha, divide)
channel-legend-spot = spot: o fator pelo qual os termos desta luz são multiplicados (0 fora do cone, 1 sem foco)
channel-legend-n-dot-l = N·L = cos θ: um cosseno, abaixo de 0 onde a superfície está voltada para o lado oposto à luz
channel-legend-n-dot-h = N·H = cos β: o cosseno especular antes da potência (regra de Blinn-Phong; R·V com Phong)
channel-legend-r-dot-v = R·V: o cosseno especular antes da potência (regra de Phong; N·H com Blinn-Phong)
channel-legend-light-count = Quantas luzes chegam ao píxel: uma contagem
case-rules-note = nota: { $path } usa as regras { $rules }; um caso segue sempre as do OpenGL
cost-wrote = escrito { $files } em { $out }

## io-errors

set-folder-is-a-link = uma ligação para outra pasta: o phonglab só escreve um conjunto de ficheiros numa pasta verdadeira, nunca através de uma ligação
set-folder-replaced = movida ou substituída (por uma ligação ou outra pasta) enquanto o phonglab escrevia o conjunto: nada foi escrito, movido ou removido através dela (o phonglab segurava a própria pasta); o conjunto não foi escrito, e o que tinha começado foi removido da pasta que segurava
set-staging-replaced = a pasta de trabalho { $name } do phonglab, lá dentro, foi movida ou substituída (por uma ligação ou outra pasta) enquanto o phonglab escrevia o conjunto: nada foi escrito, movido ou removido através dela (o phonglab segurava a própria pasta de trabalho); o conjunto não foi escrito
set-staging-taken = a pasta de trabalho { $name } do phonglab foi movida ou substituída (por uma ligação ou outra pasta) no momento em que o phonglab a criou, antes de ser aberta: nada foi escrito, movido ou apagado nela nem através dela; o conjunto não foi escrito
set-folder-replaced-asked = foi movida ou substituída (por uma ligação ou outra pasta) enquanto o phonglab escrevia o conjunto. Antes de cada passo que dá pelo nome da pasta, o phonglab verifica que ainda é a pasta que segura, e parou no primeiro em que não era (um programa fora das regras do Windows, como um programa Unix sob o Wine, pode mudar o nome de uma pasta que o Windows segura); o conjunto não foi escrito, e o que o phonglab tinha movido voltou ao lugar onde as pastas o permitiram
set-staging-replaced-asked = a pasta de trabalho { $name } do phonglab foi movida ou substituída (por uma ligação ou outra pasta) enquanto o phonglab escrevia o conjunto. Antes de cada passo que dá pelo nome de uma pasta, o phonglab verifica que ainda é a pasta que segura, e parou no primeiro em que não era (um programa fora das regras do Windows, como um programa Unix sob o Wine, pode mudar o nome de uma pasta que o Windows segura); o conjunto não foi escrito. { $now }
set-staging-now-at = O phonglab encontrou essa pasta de trabalho em { $path }, pela sua identidade: o que não conseguiu pôr de volta nem apagar está lá
set-staging-now-gone = Essa pasta de trabalho já não está onde o phonglab a criou, e o phonglab não sabe dizer onde está: o que o phonglab não conseguiu pôr de volta está nela
set-held-folder-moved = a pasta { $name } do phonglab foi movida ou substituída (por uma ligação ou outra pasta) enquanto o phonglab trabalhava nela: antes de cada passo que dá pelo nome da pasta, o phonglab verifica que ainda é a pasta que segura, e não deu este passo
set-record-not-one = uma ligação, ou algo que não é um ficheiro normal que o phonglab possa ter escrito (um pipe, um dispositivo, uma pasta, ou um ficheiro com mais de 1 MiB), onde o phonglab guarda a lista dos ficheiros que escreveu nesta pasta: o phonglab nunca lê nem escreve através dela. Remova-a, ou escolha outra pasta
set-record-not-phonglabs = não é uma lista escrita pelo phonglab (não está na forma do phonglab: foi escrita à mão ou por outro programa), onde o phonglab guarda a lista dos ficheiros que escreveu nesta pasta: o phonglab não confia nela, por isso não sabe que ficheiros aqui escreveu, e deixa-a como está. Remova-a, ou escolha outra pasta
set-record-not-own = não é só deste utilizador (pertence a outro utilizador, ou outros podem escrevê-la), onde o phonglab guarda a lista dos ficheiros que escreveu nesta pasta: qualquer pessoa pode escrever uma lista na forma do phonglab, por isso o phonglab só confia numa que mais ninguém possa ter escrito; não sabe que ficheiros aqui escreveu, e deixa a lista como está. Nada foi escrito, movido ou apagado. Se não foi o utilizador a pô-la ali, foi outro utilizador: veja-a, apague-a, ou escolha outra pasta
set-waiting-for-lock = à espera: outro phonglab está a escrever em { $dir }; este continua quando ele terminar
set-staging-left = o novo conjunto está completo em { $dir }; a pasta de trabalho { $name } do phonglab, lá dentro, ainda não pôde ser removida (um ficheiro nela pode estar ainda aberto noutro programa): a próxima execução nesta pasta remove-a
set-left-alone = { $name } em { $dir } ficou como estava: { $why }
set-name-differs-in-case = { $other } está lá, um nome que só difere do { $name } do conjunto em maiúsculas e minúsculas: o Windows toma os dois por um só ficheiro, e o conjunto poderia substituir ou perder o errado. Mude o nome de { $other } ou mova-o, ou escolha outra pasta
set-file-replaced-meanwhile = foi substituído enquanto o phonglab escrevia o conjunto (por uma ligação, ou um ficheiro que o phonglab não escreveu): ficou como estava, e nada do novo conjunto foi posto no lugar
set-why-not-all-own = contém algo que o phonglab não lá pôs (uma ligação, uma pasta ou um ficheiro): isso ficou como estava, com a pasta. Veja-o, e apague-o se não for seu
set-why-loose-journal = um diário que o phonglab não escreveu ali (posto por alguém, ou deixado por uma versão antiga do phonglab); nada do que nomeia foi tocado
set-why-not-a-folder = tem o nome das pastas temporárias do phonglab mas não é uma pasta criada pelo phonglab; nada foi seguido nem tocado
set-why-no-journal = uma pasta com o nome das pastas temporárias do phonglab, sem o diário do phonglab; nada do que contém foi tocado
set-untrusted-journal = o seu diário não foi escrito ali pelo phonglab ({ $why }); nada foi tocado
set-why-not-a-journal = não é um diário do phonglab
set-why-not-own = não é só deste utilizador (pertence a outro utilizador, ou outros podem escrevê-lo), e qualquer pessoa pode escrever um diário na forma do phonglab
set-why-folder-not-own = uma pasta com nome de pasta de trabalho do phonglab que não é só deste utilizador (foi feita por outro utilizador, ou outros podem escrever nela): o phonglab não confia em nada do que tem; nada nela foi tocado
set-why-other-folder = não nomeia a pasta onde está
set-why-outside = nomeia ficheiros fora da sua pasta
set-why-unfinished = os ficheiros de uma execução interrompida não puderam ser postos no lugar sem substituir ficheiros alterados ou criados depois ({ $names }); os novos ficam guardados nessa pasta
file-kind-cases = ficheiros de casos
png-cannot-encode = não foi possível codificar o PNG
png-too-large = imagem grande demais
png-colour-type = { $path }: tipo de cor inesperado { $kind }
pdf-cannot-write = não foi possível escrever o PDF: { $error }
err-scale = --scale { $scale }: de 0,5 a 4
err-spin = --spin tem de ser um número finito de graus
err-threads = --threads { $asked }: esta máquina corre no máximo { $most } threads ao mesmo tempo; peça { $most } ou menos (0: um por núcleo)
err-no-such-light = --light { $light }: { $count ->
    [0] a cena não tem nenhuma luz
    [one] a cena tem uma luz, a número 0
   *[other] a cena tem { $count } luzes, numeradas de 0 a { $last }
}
err-study-stopped = o estudo parou
err-rules = --rules { $value }: experimente worksheet ou opengl
err-effects = --effects: { $value } não é um destes: { $names }
err-effects-empty = --effects tem um nome vazio (uma vírgula sem nada depois ou antes dela): escreva os nomes de entre { $names }, separados por vírgulas.
err-out-is-a-file = --out { $out } é um ficheiro, e o phonglab exercise escreve os seus ficheiros numa pasta: indique uma pasta, ou o nome de uma pasta nova (nada foi escrito).
err-level = --level vai de 1 a 4
err-target = --target { $value }: experimente glsl ou wgsl
err-shading = --shading { $value }: experimente gouraud ou phong
err-not-case-file = não é um ficheiro de casos
err-cases-failed = { $failed } de { $all } casos falharam (o seu "error" diz porquê)
err-unknown-preset = cena pronta desconhecida { $value }: experimente { $names }
err-bench-frame-obj = --bench-frame desenha a esfera, o bule ou o cilindro de referência; use --obj sem ele
err-scene-to-render = a cena a desenhar
err-bench-object = --object { $value }: os objetos de referência são sphere (esfera) e teapot (bule)
err-bench-shading = --shading { $value }: os sombreamentos são gouraud, phong e flat
err-bench-slices = --slices { $value }: a esfera aceita de 3 a 2048 fatias (a de referência tem 50)
err-bench-scan = --scan { $value }: a malha tipo digitalização aceita níveis de 0 a 9 (o 8 dá 1 310 720 triângulos)
err-study-timeout = o estudo não terminou em 5 minutos
err-needs-window = este comando desenha a janela: execute-o com o programa phonglab
screenshot-summary = { $path }: { $width }x{ $height } px; imagens de { $pictures } pontos, o círculo unitário do gráfico com { $circle } pontos de diâmetro, { $empty } % vazio
screenshot-none = nenhum
bench-render-header = phonglab bench render: { $size }x{ $size } px, { $frames } imagens, { $threads } threads; ms médios das etapas: vértices, preparação, rasterização, resolução
bench-lighting-header = phonglab bench lighting: { $vertices } vértices, a melhor de { $repeats }, uma thread, f32
bench-memory-floor = limite da memória: os mesmos arrays lidos e escritos sem iluminação, { $ns } ns por vértice ({ $gbs } GB/s dos { $bytes } bytes que um vértice move)
bench-stages-header = onde se gasta o tempo especializado (ns por vértice; ler o relógio soma ~0,2 por etapa)
bench-ui-present-header = phonglab bench ui --present: { $width }x{ $height } pontos, modo de apresentação com a gaveta dos controlos aberta, { $frames } imagens por caso; em cada imagem o z da luz move-se como o move um slider arrastado; ms de CPU (o layout inclui o cálculo da cena e o desenho da vista sombreada)
bench-ui-header = phonglab bench ui: { $width }x{ $height } pontos, todos os painéis abertos, { $frames } imagens por caso, ms de CPU (o layout inclui o cálculo da cena e o desenho da vista sombreada quando mudou)
err-lang = { $value }: o phonglab fala en, pt-PT e pt-BR
err-decimal = { $value }: point (ponto) ou comma (vírgula)

## cost

cost-axis-ms = ms por imagem (log)
cost-axis-error = erro médio, 1/255 (log)
cost-rounding = arredondamento a 8 bits
cost-variant = variante
cost-triangles = triângulos
cost-ms = ms/imagem
cost-mean = média /255
cost-max = máx. /255
cost-cheapest = O mais barato com menos de 1 % dos píxeis a mais de 1/255: { $variant } ({ $triangles } triângulos), { $ms } ms por imagem.
cost-none-within = Nenhum sombreamento estudado fica a menos de 1/255 em 99 % dos píxeis: a silhueta ou o brilho pedem uma malha mais fina.
cost-precision = f32 contra f64 em { $vertices } vértices: no máximo { $apart } de diferença ({ $shown }/255 depois de limitar); o motor geral leva { $f32 } ns (f32) e { $f64 } ns (f64) por vértice, o especializado { $specialised } ns.
cost-intro = Cada sombreamento em cinco tesselações do objeto atual, cronometrado e comparado com uma referência: Phong por píxel em f64 numa malha muito fina. Também Phong em f32 na própria malha da referência (o f64 muda algo visível?) e as aproximações mais usadas.
cost-run = Correr o estudo
cancel = Cancelar
cost-about = { $about } ({ $size }x{ $size } px, tempos medidos com a aplicação a correr)
cost-table = Tabela
heat-map-computing = Mapa de calor do erro: a calcular a referência...
heat-map-caption = Erro face à referência f64: média { $mean }/255, máximo { $max }/255, { $share } % dos píxeis > 1/255 (branco: { $white }/255)
cost-failed = O estudo falhou: { $error }
heat-map-failed = O mapa de calor falhou: { $error }
work-starting = a começar
work-failed = o cálculo falhou inesperadamente
work-no-pool = sem conjunto de threads: { $error }
work-stopped = o cálculo parou
cost-table-title = { $object }: { $size }x{ $size } px, referência com { $triangles } triângulos (f64, por píxel); erros em 1/255 em relação a ela
cost-over-column = >1/255 %
cost-chart-title = { $object }: tempo por imagem contra erro médio ({ $size }x{ $size } px, referência: Phong por píxel em f64, { $triangles } triângulos)

## cli

cli-about = Um explorador da iluminação por vértice da função fixa do OpenGL e dos sombreamentos de Gouraud, Phong e Flat
cli-lang = A língua do que o phonglab diz: en, pt-PT ou pt-BR (por omissão, a do sistema: LC_ALL, LC_MESSAGES ou LANG, se alguma estiver definida; senão, no Windows, a língua de apresentação do utilizador e, no macOS, a sua língua preferida). JSON, CSV e ficheiros de cena mantêm as chaves em inglês
cli-decimal = Como se escrevem os números para pessoas: point (0.5) ou comma (0,5); por omissão, o da língua (vírgula em português). Os números escritos leem-se com qualquer um
cli-memory-budget = A memória que um comando pode ocupar com o que lhe é pedido (o tamanho de uma imagem, uma malha): 512M, 8G, ...; por omissão: metade da que o sistema tem disponível. Acima dela, um comando diz quanto precisa e não começa
cli-eval = Calcular casos glref (JSON) e imprimir as cores iluminadas em JSON
cli-explain = Imprimir o cálculo da cor de um vértice, passo a passo, pela ordem da ficha
cli-render = Desenhar a vista sombreada (esfera, bule ou cilindro) num PNG
cli-exercise = Escrever fichas de exercícios ao estilo da ficha, com ficheiros de cena e chaves de respostas
cli-shader = Imprimir o shader (GLSL 3.30 ou WGSL) que desenha a vista sombreada de uma cena: só as etapas de que precisa
cli-case = Escrever ficheiros de cena como casos glref (JSON), para os comparar com um OpenGL real
cli-cost = O custo da exatidão: cada sombreamento e tesselação, f32 contra f64 e as aproximações habituais, cronometrados e comparados com uma referência f64 por píxel; escreve cost.csv e cost.png
cli-bench = Medir: o desenho, a iluminação
cli-screenshot = Desenhar a janela inteira sem ecrã nem GPU num PNG: para diapositivos, fichas e testes

## cli-args

cli-usage = Utilização:
cli-heading-commands = Comandos
cli-heading-arguments = Argumentos
cli-heading-options = Opções
cli-flag-help = Mostrar a ajuda
cli-flag-version = Mostrar a versão
cli-help-command = Mostrar esta mensagem ou a ajuda do subcomando indicado
cli-default = [por omissão: { $value }]
cli-possible-values = [valores: { $values }]
cli-bench-render = ms por imagem do desenho no CPU, na cena de referência
cli-bench-lighting = ns por vértice da iluminação geral e da especializada
cli-bench-ui = Tempo de CPU por imagem da interface inteira, sem ecrã, com todos os painéis abertos
cli-arg-app-file = Um ficheiro de cena (TOML) com que abrir a aplicação; se não se puder ler, abre a ficha e diz porquê (uma palavra sem ponto que não nomeia nenhum ficheiro é tomada por um comando mal escrito)
cli-arg-app-renderer = Quem desenha a vista sombreada da aplicação: a GPU quando o adaptador é uma GPU a sério, senão o desenho no CPU
cli-arg-eval-cases = Um ficheiro JSON de casos (uma lista, ou {"{"}"cases": [...]{"}"}), como em docs/lighting.md
cli-arg-eval-precision = A precisão do motor de cálculo
cli-arg-eval-clamp = Limitar as cores a [0, 1], como o OpenGL faz por omissão (senão, sem limite)
cli-arg-eval-pow = A função potência dos termos especular e do foco
cli-arg-explain-scene = Um ficheiro de cena (TOML), como a aplicação o guarda
cli-arg-explain-worksheet = A cena da ficha com a modelview N (1-5). Sem cena indicada, a 5
cli-arg-explain-preset = Em vez disso, uma cena pronta: "phong-demo"
cli-arg-explain-precision = A precisão do motor de cálculo
cli-arg-explain-back = Explicar a face de trás (iluminação das duas faces)
cli-arg-explain-markdown = Imprimir uma tabela Markdown em vez de texto
cli-arg-explain-digits = Algarismos significativos
cli-arg-render-object = O objeto (por omissão, o da cena)
cli-arg-render-obj = Sombrear esta malha Wavefront OBJ em vez do objeto da cena (ajustada ao raio 0,5)
cli-arg-render-shading = O sombreamento (por omissão, o da cena)
cli-arg-render-size = Largura e altura da imagem em píxeis
cli-arg-render-output = O PNG a escrever
cli-arg-render-scene = Um ficheiro de cena (TOML); por omissão, a cena da ficha
cli-arg-render-preset = Em vez disso, uma cena pronta: "worksheet" ou "phong-demo"
cli-arg-render-bench_frame = Em vez disso, a cena de referência de docs/lighting.md nesta imagem (esfera r 1 50x50, bule 0,8, gluPerspective(40, 1, 0.5, 20)): a imagem que o arnês do Mesa desenha
cli-arg-render-pow = A função potência dos termos especular e do foco
cli-arg-render-cull = Descartar as faces de trás
cli-arg-render-frame = A imagem N da rotação da cena: N passos de 0,5 graus (a primeira imagem que a demo de Phong desenha é a 1). Por omissão, a rotação da própria cena
cli-arg-render-correct = Corrigir os desvios da demo de Phong à iluminação do OpenGL (separados por vírgulas): light (fixa no mundo), normals (as verdadeiras da superfície), highlight (na cor da luz) ou all
cli-arg-probe-object = O objeto (por omissão, o da cena)
cli-arg-probe-obj = Sombrear esta malha Wavefront OBJ em vez do objeto da cena (ajustada ao raio 0,5)
cli-arg-probe-shading = O sombreamento (por omissão, o da cena)
cli-arg-probe-size = Largura e altura da imagem em píxeis
cli-arg-probe-scene = Um ficheiro de cena (TOML); por omissão, a cena da ficha
cli-arg-probe-preset = Em vez disso, uma cena pronta: "worksheet" ou "phong-demo"
cli-arg-probe-bench_frame = Em vez disso, a cena de referência de docs/lighting.md nesta imagem (esfera r 1 50x50, bule 0,8, gluPerspective(40, 1, 0.5, 20)): a imagem que o arnês do Mesa desenha
cli-arg-probe-pow = A função potência dos termos especular e do foco
cli-arg-probe-cull = Descartar as faces de trás
cli-arg-probe-frame = A imagem N da rotação da cena: N passos de 0,5 graus (a primeira imagem que a demo de Phong desenha é a 1). Por omissão, a rotação da própria cena
cli-arg-probe-correct = Corrigir os desvios da demo de Phong à iluminação do OpenGL (separados por vírgulas): light (fixa no mundo), normals (as verdadeiras da superfície), highlight (na cor da luz) ou all
cli-probe = Porque é que um píxel da vista sombreada tem a sua cor: o triângulo, os pesos, os vértices ou o fragmento, cada termo, o limite e o arredondamento a 8 bits
cli-arg-probe-at = O píxel: x a partir da esquerda, y a partir do topo, desde 0
cli-arg-probe-json = Imprimir JSON (para scripts e testes) em vez do relatório
cli-arg-render-channel = Desenhar um termo da equação de iluminação em falsa cor em vez da imagem
cli-arg-render-light = A luz do canal, pela sua posição entre as luzes ligadas (0 a primeira); sem ela, os termos de cor somam todas as luzes
cli-arg-render-colour_map = O mapa da falsa cor
cli-arg-render-raw = Escrever também os valores do canal, sem limitar, num mapa de floats portátil (PFM)
cli-share = Uma cena como ligação para a versão do navegador (a cena vai na própria ligação), e como código QR para uma turma
cli-arg-share-scene = O ficheiro de cena (TOML); por omissão: a cena da ficha
cli-arg-share-base = A página que a ligação abre
cli-arg-share-open_in = Abri-la nesta língua (en, pt-PT, pt-BR)
cli-arg-share-present = Abri-la a apresentar a uma turma
cli-arg-share-channel = Abri-la a mostrar este termo em vez da imagem
cli-arg-share-qr = Escrever também a ligação como código QR: FICHEIRO.png ou FICHEIRO.svg
cli-value-emission = a emissão do material, e_cm
cli-value-scene-ambient = o ambiente da cena, a_cm a_cs
cli-value-ambient = o ambiente de cada luz, após atenuação e foco
cli-value-diffuse = a difusa de cada luz, após atenuação e foco
cli-value-specular = a especular de cada luz, após atenuação e foco
cli-value-attenuation = o fator de atenuação de uma luz, 1/at (o at da ficha, k0 + k1 d + k2 d², divide)
cli-value-spot = o fator do foco de uma luz
cli-value-n-dot-l = o n · L de uma luz
cli-value-n-dot-h = o n · H de uma luz
cli-value-normal = a normal com que o píxel é iluminado, como cor
cli-value-light-count = quantas luzes chegam ao píxel
cli-value-viridis = viridis (azul-escuro, verde, amarelo)
cli-value-cividis = cividis (azul a amarelo), feito para o daltonismo vermelho-verde
cli-arg-exercise-seed = A semente aleatória: a mesma semente dá as mesmas fichas
cli-arg-exercise-count = Quantos exercícios
cli-arg-exercise-level = Dificuldade: 1 só direcional, 2 pontual com atenuação, 3 focos, 4 duas faces com várias luzes; 5 "o que está errado nesta imagem?" (uma imagem por erro, sete no máximo)
cli-arg-exercise-effects = Exatamente estes efeitos em vez de um nível (separados por vírgulas): positional, attenuation, spot, local-viewer, two-sided, several-lights
cli-arg-exercise-rules = As regras que as respostas seguem: worksheet (as da ficha) ou opengl
cli-arg-exercise-worksheet = Escrever também o exercício 0: a própria ficha, as suas cinco modelviews numa folha
cli-arg-exercise-out = A pasta onde escrever (criada se não existir)
cli-arg-exercise-format = O que escrever: as fichas, as chaves e os PDF; ou um ficheiro para o banco de questões do Moodle
cli-arg-exercise-variants = Com um formato do Moodle: este número de variantes de cada exercício, tiradas da semente, uma categoria por exercício, para a pergunta aleatória de um teste
cli-arg-exercise-category = Com um formato do Moodle: o nome da categoria de topo (phonglab por omissão)
cli-arg-exercise-exam = Exercícios de exame, resolvidos sem calculadora: vetores unitários pitagóricos, distâncias inteiras, brilho 1, 2 ou 4, quatro algarismos significativos à mão
cli-value-sheets = fichas, chaves, ficheiros de cena e os dois PDF
cli-value-moodle-xml = questions.xml em Moodle XML: uma pergunta Cloze por exercício, imagens incluídas
cli-value-gift = questions.gift.txt em GIFT: uma pergunta numérica por valor
cli-arg-shader-scene = Um ficheiro de cena (por omissão, o da ficha, mview5)
cli-arg-shader-target = glsl (3.30 core: um shader de vértices e um de fragmentos) ou wgsl (um módulo)
cli-arg-shader-shading = gouraud (iluminado por vértice) ou phong (iluminado por fragmento)
cli-arg-case-scenes = Ficheiros de cena (TOML); cada um dá um caso, com o nome do ficheiro sem extensão como id
cli-arg-cost-object = O objeto a estudar (por omissão, os três)
cli-arg-cost-out = Onde escrever cost.csv, cost.png e os mapas de calor
cli-arg-cost-size = Largura e altura da imagem em píxeis
cli-arg-cost-scene = Um ficheiro de cena (TOML) para a iluminação e a vista; por omissão, a cena da ficha
cli-arg-cost-spin = Rodar o objeto estes graus em torno de y (a 30, o cilindro mostra o lado)
cli-arg-cost-threads = Threads para desenhar (por omissão, todos os núcleos)
cli-arg-cost-quick = Tempos rápidos (3 imagens ou 0,1 s por variante) em vez de cuidadosos
cli-arg-bench-render-frames = Imagens cronometradas por objeto e sombreamento (depois de 5 de aquecimento)
cli-arg-bench-render-size = Tamanho da imagem em píxeis (quadrada)
cli-arg-bench-render-threads = Threads de trabalho (por omissão, uma por núcleo)
cli-arg-bench-render-object = Só este objeto: sphere (esfera) ou teapot (bule) (por omissão, os dois)
cli-arg-bench-render-shading = Só este sombreamento: gouraud, phong ou flat (por omissão, os três)
cli-arg-bench-render-slices = As fatias e camadas da esfera, de 3 a 2048 (a de referência tem 50): o custo em função do número de triângulos
cli-arg-bench-render-mesh = Medir o tempo desta malha OBJ (ajustada à vista) em vez da esfera e do bule
cli-arg-bench-render-scan = Medir o tempo da malha tipo digitalização de 20 x 4^NÍVEL triângulos (um icosaedro subdividido, irregular e rugoso; o 8 dá 1 310 720) em vez da esfera e do bule
cli-arg-bench-render-write_mesh = Escrever a malha que seria cronometrada (--mesh, --scan ou a esfera de --slices, tal como fica na vista de referência) num ficheiro OBJ, sem cronometrar nada: os mesmos vetores de vértices para o banco de ensaio do Mesa (benches/compare_llvmpipe.py)
cli-arg-bench-render-moving = O que muda de fotograma para fotograma: object (o objeto roda 3 graus por fotograma, cada fotograma desenhado por inteiro) ou light (a luz circula à volta do objeto parado, como quando um aluno a arrasta: a visibilidade é guardada e só a iluminação e o sombreamento correm de novo)
cli-arg-bench-render-coarse = Cronometrar a cópia grosseira de cerca de tantos triângulos em vez da própria malha: o que a aplicação desenha enquanto a câmara roda sobre uma malha muito grande (diz quanto tempo levou a fazer a cópia)
cli-arg-bench-lighting-vertices = Vértices por cena
cli-arg-bench-lighting-repeats = Repetições cronometradas (diz-se a melhor)
cli-arg-bench-lighting-stages = Dizer também onde se gasta o tempo da iluminação especializada: ns por vértice a carregar, em cada etapa do programa da cena e a escrever
cli-arg-bench-ui-frames = Imagens cronometradas por caso
cli-arg-bench-ui-width = Largura da janela em pontos
cli-arg-bench-ui-height = Altura da janela em pontos
cli-arg-bench-ui-present = Modo de apresentação (letra grande, a gaveta dos controlos aberta) a 1920x1080, salvo outro tamanho: a luz é arrastada com sombreamento de Gouraud e depois de Phong
cli-arg-screenshot-size = O tamanho da janela em pontos, LARGURAxALTURA
cli-arg-screenshot-scale = Píxeis por ponto (2 para um ecrã de alta densidade)
cli-arg-screenshot-present = Modo de apresentação (F5)
cli-arg-screenshot-light = O tema claro (por omissão, o escuro)
cli-arg-screenshot-scene = Um ficheiro de cena (por omissão, a cena da ficha)
cli-arg-screenshot-open = Abrir isto primeiro
cli-arg-screenshot-output = O PNG a escrever
cli-value-auto = a GPU quando o adaptador é uma GPU a sério, senão o CPU
cli-value-cpu = o desenho no CPU (a referência)
cli-value-gpu = a GPU, mesmo um adaptador por software
cli-value-f32 = precisão simples, como o OpenGL calcula
cli-value-f64 = precisão dupla
cli-value-exact = a pow exata da biblioteca
cli-value-llvmpipe = a aproximação exp2(e log2 x) do llvmpipe do Mesa, igual bit a bit ao Mesa 22.3
cli-value-schlick = a aproximação racional de Schlick
cli-value-sphere = gluSphere (esfera)
cli-value-teapot = o bule de Utah
cli-value-cylinder = gluCylinder (cilindro)
cli-value-gouraud = iluminação por vértice, cores interpoladas
cli-value-phong = iluminação por píxel
cli-value-flat = um cálculo por face
cli-value-light = a luz fixa no mundo
cli-value-normals = as normais verdadeiras da superfície
cli-value-highlight = o brilho especular na cor da luz
cli-value-all = as três
cli-value-compare = Comparar, com a cena fixada como A e, como B, a mesma cena com sombreamento de Phong
cli-value-lobe = o lóbulo de reflexão no lugar do gráfico
cli-value-quiz = o teste sobre a cena
cli-value-shader = a janela do Shader
cli-value-cost = a janela do Custo da exatidão
cli-value-demo-fixes = as três correções da demo de Phong, lado a lado com a imagem da própria demo
cli-stopped = { $how ->
        [ctrl-c] parado com Ctrl+C.
       *[asked] parado: o sistema pediu-lhe que terminasse.
    } Nenhum ficheiro ficou escrito a meio (cada um é escrito por inteiro ou não é escrito); corra o comando de novo para o que ainda não tinha escrito.
app-cannot-open-window =
    não é possível abrir a janela: { $error }
    (sem ecrã? os subcomandos funcionam sem ecrã: phonglab --help)

## phonglab diagnose: a imagem de um aluno verificada

cli-diagnose = A imagem que um aluno fez de uma cena, verificada: certa, que erro a fez, ou nenhum que o phonglab conheça; uma imagem das diferenças e a sonda onde mais difere. Código de saída: 0 certa, 1 errada ou não explicada, 2 erro de utilização ou de entrada
cli-arg-diagnose-scene = A cena para a qual a imagem foi feita (TOML)
cli-arg-diagnose-image = A imagem do aluno (PNG), feita com a câmara e o tamanho da exportação
cli-arg-diagnose-size = A largura e a altura da imagem em píxeis: a janela da exportação tem 512
cli-arg-diagnose-diff = Escrever a imagem das diferenças (a imagem contra a certa) neste PNG
cli-arg-diagnose-json = Imprimir JSON (para scripts e testes) em vez do relatório
file-kind-pictures = imagens
diagnose-bad-png = { $path } não pode ser lido como uma imagem PNG: { $reason }
diagnose-transparent = { $path } tem { $count } píxeis transparentes ou translúcidos (alfa abaixo de 255): o que mostram depende do que está por trás, por isso o phonglab não a avalia. Guarde a imagem opaca, como a guardam a exportação e uma captura de ecrã da janela.
png-reason-jpeg = é uma imagem JPEG, e o phonglab só diagnostica PNG (as perdas de um JPEG podem esconder a causa): guarde a imagem como PNG diretamente do programa (com a opção --png do programa exportado), ou converta-a (convert imagem.jpg imagem.png)
png-reason-not-png = não é um ficheiro PNG (não começa pela assinatura de um PNG)
png-reason-too-large = é demasiado grande para descodificar
png-reason-damaged = o ficheiro está danificado ou incompleto
png-reason-colours = as suas cores estão guardadas como { $kind }, que o phonglab não lê
diagnose-wrong-size = { $path } tem { $got } píxeis; a imagem desta cena tem { $expected }. Guarde o PNG do programa com a opção --png, que desenha a cena nesse tamanho: uma captura de ecrã de uma janela não é o desenho. (Uma cena desenhada noutro tamanho verifica-se com phonglab diagnose --size.)
diagnose-invisible = Não se distinguem da imagem certa (nesta cena, cada um desenha-a dentro do que uma imagem permite dizer): { $ids }
diagnose-diff-written = Imagem das diferenças escrita em { $path }: { $said }
diagnose-diff-not-png = --diff { $path }: a imagem da diferença é um PNG e o seu nome tem de terminar em .png (o check leria um nome terminado em .ipynb, .py ou .txt como um trabalho de um aluno); nada foi escrito.
diagnose-worst = O píxel que mais difere: ({ $x }, { $y }), a sua imagem { $image } contra a certa { $right }. A sonda da imagem certa nesse ponto:

## phonglab check: o trabalho de um aluno verificado

check-nothing-printed = nada impresso que a solução tenha: imprima cada valor como a ficha faz, print("vlv = ", vlv)
check-report-scene = Enunciado: { $scene }
check-report-title = Verificação da turma
check-report-student = Aluno
check-report-verdict = Veredicto
check-report-first-wrong = Primeiro passo errado
check-report-causes = Causas
check-report-counts = Causas na turma
check-report-unexplained = não explicado pelo catálogo
check-report-unreadable = não lido: { $reason }
check-class-checked = { $count ->
    [one] um trabalho verificado
   *[other] { $count } trabalhos verificados
}{ $unread ->
    [0] {""}
    [one] {", "}um não lido
   *[other] {", "}{ $unread } não lidos
}
check-class-report-written = relatório escrito em { $path } (o gráfico, em { $chart })
check-class-marks-written = notas escritas em { $path }
check-printed-with-folder = --printed verifica o texto impresso por um programa; os cadernos de uma pasta são lidos dos seus próprios resultados: indique um ou outro
check-report-needs-folder = --report e --csv são de uma turma: indique uma pasta de cadernos (a verificação de um caderno é escrita no terminal, ou com --json)
check-not-read-time = não lido: a verificação da turma esgotou os seus { $seconds } s (os ficheiros mais pequenos são verificados primeiro)
check-too-many-notebooks = { $folder } tem mais de { $max } cadernos: não é a pasta de uma turma; nada foi verificado nem escrito
check-not-read-link = uma ligação simbólica (um trabalho tem de ser um ficheiro da própria pasta)
check-not-read-folder = uma pasta (um trabalho é um ficheiro de caderno)
check-not-read-not-a-file = não é um ficheiro normal (um FIFO ou um dispositivo: um trabalho é um ficheiro de caderno)
check-chart-link = { $path } é uma ligação simbólica: o nome do gráfico vem do do relatório, e o phonglab nunca escreve através de uma ligação que não lhe foi dada; apague a ligação ou dê outro nome ao relatório
work-output-link = { $path } é uma ligação simbólica: o check e o diagnose nunca escrevem através de uma ligação, que pode levar a qualquer ficheiro (numa pasta da turma, pode ter sido um aluno a pô-la lá); nada foi escrito. Apague a ligação ou indique outro ficheiro
work-output-not-ours = { $path } já existe e não foi o phonglab que o escreveu (não é um resultado anterior do phonglab: { $kind }): o check e o diagnose nunca substituem um ficheiro que pode ser de um aluno; nada foi escrito. Indique outro nome, ou tire primeiro esse ficheiro daí
work-output-other-kind = { $path } já existe e é um resultado do phonglab, mas { $found }, não { $kind }: o check e o diagnose só substituem um ficheiro por outro novo do mesmo tipo, para que um resultado nunca tome o lugar de outro; nada foi escrito. Indique outro nome, ou tire primeiro esse ficheiro daí
work-output-submission = { $path } está dentro da pasta verificada e tem nome de trabalho de aluno (.ipynb ou .py): a próxima verificação lê-lo-ia como um trabalho; dê-lhe, por exemplo, o nome { $suggested }, ou escreva-o fora da pasta
work-output-kind-report = o relatório da turma (check --report)
work-output-kind-marks = as notas (check --csv)
marks-column-file = ficheiro
marks-column-verdict = veredicto
marks-column-first-wrong = primeiro passo errado
marks-column-causes = causas
marks-column-cause-ids = ids das causas
marks-column-verdict-id = id do veredicto
work-output-kind-chart = o gráfico das causas (check --report)
work-output-kind-difference = a imagem das diferenças (diagnose --diff)
check-chart-title = Causas na turma ({ $count } trabalhos)
check-verdict-word-right = certo
check-verdict-word-wrong = errado
check-scene-own = cena: a do próprio caderno (os dados escritos nele são tomados como o enunciado e não podem estar errados; indique o enunciado com --scene S.toml)
check-scene-file = cena: { $path }
check-scene-printed = cena: a da ficha (o enunciado com --scene S.toml)
check-report-no-scene = Não foi indicada nenhuma --scene: os dados escritos em cada caderno foram tomados como o enunciado do próprio aluno e não podem estar errados (um brilho de 0,2 em vez de 0,2*128 passa). Indique a cena do enunciado com --scene S.toml.
check-verdict-word-unread = não lido
check-verdict-word-incomplete = incompleto
check-report-unread = Não lidos
check-report-unchecked = incompleto (um passo não impresso, saídas fora de ordem, a execução parou, dígitos a menos para decidir, ou nada comparado)
cli-check = Verificar o trabalho de um aluno: um caderno da ficha com os resultados, o texto impresso por um programa, ou uma pasta deles; cada passo impresso comparado com a solução, o primeiro passo errado e as causas prováveis. Código de saída: 0 certo, 1 errado ou não verificado, 2 erro de utilização ou de entrada; para uma pasta, 0 depois de escrito o relatório
cli-arg-check-work = O caderno (.ipynb, guardado com os resultados), ou uma pasta deles para a turma toda
cli-arg-check-printed = O texto impresso por um programa, em vez de um caderno (- para a entrada padrão)
cli-arg-check-scene = A cena do enunciado (TOML); por omissão: a do próprio caderno (a da ficha para texto impresso)
cli-arg-check-json = Escrever a verificação em JSON
cli-arg-check-report = Para uma pasta: o relatório da turma a escrever (Markdown), com o gráfico de barras ao lado (.png)
cli-arg-check-csv = Para uma pasta: as notas a escrever (CSV)
student-menu = Corrigir o trabalho de um aluno…
student-menu-hover = Um caderno da ficha guardado com as saídas (.ipynb) ou o texto que um programa imprimiu (.txt), corrigido com a cena mostrada: o valor do aluno ao lado de cada passo, o primeiro passo errado e as causas prováveis; ou uma imagem que o programa dele desenhou (.png, 512 x 512), diagnosticada em Comparar. Nada do que lá está é executado.
student-choose-why = Escolha o caderno do aluno (guardado com as saídas, .ipynb), o texto impresso (.txt) ou a imagem (.png, 512 x 512).
student-choose-filter = Caderno, texto impresso ou imagem
student-check = Corrigir
student-own-scene = { $count } dos valores que escreveu diferem da cena mostrada: parece escrito para outra cena, por isso é verificado contra a cena do próprio caderno (como o phonglab check sem --scene) e os seus valores não aparecem junto dos passos desta cena. É esta a cena certa? Para o corrigir contra o enunciado, abra essa cena.
student-heading = Trabalho do aluno: { $file }
student-clear = Limpar
student-clear-hover = Esconder os valores do aluno e a correção
student-value = o seu = { $student }: { $verdict }
student-first-wrong-marker = » primeiro passo errado
student-checked-own = { $file } corrigido com a cena do próprio caderno (não esta): { $verdict }
student-checked = { $file } corrigido com esta cena: { $verdict }
student-checked-wrong = nem tudo está certo; veja o cálculo
student-not-checked = Não corrigido: { $why }. A cena e o cálculo não mudaram.
student-not-work = { $path } não é um caderno (.ipynb) nem texto impresso (.txt)
student-ask-title = Um caderno com saídas
student-ask = { $file } tem valores impressos. Corrigi-los com esta cena, ou abrir o caderno como cena?
student-ask-check = Corrigir com esta cena
student-ask-open = Abrir como cena
student-picture-heading = Imagem do aluno: { $file }
student-picture-right = A: a imagem certa desta cena
student-picture-theirs = B: a imagem do aluno
student-picture-stale = { $file } foi corrigido com a cena tal como estava quando foi aberto; a cena mostrada mudou desde então, por isso esse veredicto não é o desta cena.
student-picture-unspun = Verificada com a vista da própria cena, tal como o programa a desenha: a rotação que a janela deu ao objeto fica de fora.
student-picture-recheck = Corrigir com esta cena
student-picture-more = O diagnóstico continua abaixo: desloque-o com a barra à direita.
student-picture-difference = Diferença |A − B| × { $gain }
student-picture-difference-said = A diferença (a terceira imagem): { $said }
# fix57b
check-report-printed-twice = Passos impressos mais de uma vez com valores diferentes (cada impressão foi verificada)
# fixr3
student-cause-beside = causa provável: { $words } [{ $id }] (a prova está acima dos passos)
# fix60b
moodle-not-ours = { $path } não foi escrito pelo phonglab, ou foi alterado desde então: o phonglab não o substitui. Mova-o para outro lado, ou escolha outro --out.
set-not-ours = { $path } não foi escrito pelo phonglab, ou foi editado depois de ele o escrever: o phonglab não o substitui, e não escreveu nada. Para escrever as fichas aqui, mova esse ficheiro para outro lado (guarda as suas alterações), ou escolha outra pasta.
err-category-blank = --category precisa de um nome: está vazio ou só tem espaços.
err-category-slash = --category não pode começar nem acabar em "/": o Moodle leria mal o caminho da categoria.
err-category-control = --category tem um carácter de controlo, { $character }: o nome de uma categoria é uma só linha de texto, sem quebras de linha nem tabulações.
err-category-long = --category tem { $length } caracteres; o Moodle guarda o nome de uma categoria em { $max }, no máximo.
err-worksheet-moodle = --worksheet escreve o exercício 0 só nas fichas; um ficheiro para o Moodle usa --level ou --effects.
budget-what-moodle = um ficheiro para o Moodle com { $count ->
        [one] { $shown } exercício
       *[other] { $shown } exercícios
    } (cerca de { $size } em disco)
budget-what-sheets = um conjunto de { $count ->
        [one] { $shown } ficha de exercícios com a sua chave
       *[other] { $shown } fichas de exercícios com as chaves
    } e os dois PDF (cerca de { $size } em disco)
budget-what-wrong = um conjunto de { $count ->
    [one] uma imagem
   *[other] { $count } imagens
} com um erro cada

## arg-errors

arg-error-invalid-value = { $arg } não aceita { $value }: aceita { $values }.
arg-error-missing-value = { $arg } precisa de um valor.
arg-error-out-of-range = { $arg } aceita um número inteiro de { $low } a { $high }, não { $value }.
arg-error-not-whole = { $arg } aceita um número inteiro, não { $value }.
arg-error-not-number = { $arg } aceita um número, não { $value }.
arg-error-invalid-utf8 = Um dos argumentos não é texto em UTF-8: só o nome de um ficheiro ou de uma pasta pode ter outros bytes. Escreva os outros em UTF-8.
arg-error-refused-value = { $arg } não aceita { $value }: { $reason }
arg-error-unknown = Não existe a opção { $arg }.
arg-error-did-you-mean = Queria dizer { $suggestion }?
arg-error-unknown-command = Não existe o comando { $name }.
arg-error-unknown-command-or-file = Não existe o comando { $name }, nem um ficheiro com esse nome.
arg-error-missing = Falta indicar { $args }.
arg-error-conflict = A opção { $arg } não pode ser usada com { $other }.
arg-error-twice = { $arg } foi indicada duas vezes: indique-a uma só vez.
arg-error-unexpected = Não se esperava { $arg } aqui: não é uma opção nem o valor de uma.
arg-error-more = Veja { $help }.
# fix57c
work-output-changed = { $path } é um resultado anterior do phonglab, { $kind }, mas foi alterado depois de o phonglab o escrever (uma linha acrescentada, uma edição): o phonglab não apaga o que lá foi acrescentado; nada foi escrito. Indique outro nome (--csv notas-2.csv, --report relatorio-2.md), ou tire primeiro esse ficheiro daí
work-output-no-record = { $path } parece um resultado anterior do phonglab ({ $kind }), mas o phonglab não tem registo de o ter escrito aqui (qualquer pessoa pode escrever a sua primeira linha): não é do phonglab para substituir; nada foi escrito. Indique outro nome, ou tire primeiro esse ficheiro daí
work-output-records-untrusted = { $path } parece um resultado anterior do phonglab ({ $kind }), mas os registos do que o phonglab escreveu ({ $records }) não são só deste utilizador (outro utilizador é o dono ou pode escrever lá), por isso nenhum é de confiança; nada foi escrito. Indique outro nome, ou torne essa pasta só sua (chmod 700)
