# As mensagens do phonglab em português europeu.

## app

present = Apresentar (F5)
space-object = Objeto
space-world = Mundo
space-eye = Olho
wrong-cause-normals-by-m = Normais transformadas por M em vez da sua inversa transposta
wrong-why-normals-by-m = Com uma escala diferente em cada eixo, M move a superfície de uma maneira e as normais de outra: M n deixa de ser perpendicular à superfície, e (M^-1)^T n continua a sê-lo.
wrong-cause-normal-not-normalised = A normal não normalizada (GL_NORMALIZE desligado com uma modelview que escala)
wrong-why-normal-not-normalised = Uma modelview que escala por { $scale } torna a normal transformada de comprimento 2, e nada a traz de volta a 1: n · L duplica, e com ele o termo difuso; perto do brilho, n · H passa de 1, e a potência s_rm faz explodir o termo especular numa mancha branca.
wrong-cause-reflection-for-halfway = O vetor refletido (R · V) usado onde cabe o vetor médio (n · H)
wrong-why-reflection-for-halfway = O ângulo entre R e V é cerca do dobro do ângulo entre n e H, por isso R · V cai mais depressa: com o mesmo expoente o brilho é menor.
wrong-cause-gouraud-misses-highlight = Sombreamento de Gouraud: iluminado só nos vértices, e um brilho entre eles perde-se
wrong-why-gouraud-misses-highlight = O brilho cai entre os vértices da esfera grosseira: nenhum deles o vê, e interpolar as suas cores não o pode criar.
wrong-cause-specular-facing-away = Luz especular em faces voltadas para o lado oposto à luz (sem f_i)
wrong-why-specular-facing-away = O OpenGL multiplica o termo especular por f_i, que só vale 1 onde n · L > 0. Sem ele, n · H ainda pode ser positivo no lado escuro: brilha onde a luz não chega.
wrong-cause-attenuation-object-space = Atenuação calculada com a distância no espaço do objeto
wrong-why-attenuation-object-space = O modelo escala por { $scale }, por isso as distâncias no espaço do objeto são 4 vezes as do espaço do olho: at = k0 + k1 d + k2 d² cresce, cada termo é dividido por mais, e a luz apaga-se cedo demais. O OpenGL mede d no espaço do olho.
wrong-cause-light-before-view = A posição da luz dada antes da transformação de vista
wrong-why-light-before-view = O glLightfv(GL_POSITION) multiplica a posição pela modelview corrente nesse momento. Dada antes do gluLookAt, é tomada em coordenadas do olho: a luz anda com a câmara em vez de ficar no mundo.
wrong-probe-line = bytes { $rgba }, n · L = { $ndotl }, { $cosine } = { $ndoth }, 1/at = { $att }, difusa { $diffuse }, especular { $specular }
wrong-key-cause = Causa: { $cause }.
wrong-key-formulas = Certo: { $right }. O erro: { $wrong }.
wrong-formula-gouraud-right = iluminação em cada fragmento (Phong)
wrong-formula-gouraud-wrong = iluminação em cada vértice e cores interpoladas (Gouraud)
wrong-formula-facing-away-right = f_i = 1 só onde n · L > 0
wrong-formula-facing-away-wrong = f_i = 1 em toda a parte
wrong-formula-attenuation-right = d = |P_pli - P| no espaço do olho
wrong-formula-attenuation-wrong = d medida no espaço do objeto
wrong-formula-light-right = gluLookAt(...) e depois glLightfv(GL_POSITION, p)
wrong-formula-light-wrong = glLightfv(GL_POSITION, p) e depois gluLookAt(...)
wrong-key-pixel = A sonda no píxel ({ $x }, { $y }), onde as duas imagens mais diferem ({ $count } píxeis diferem):
wrong-key-right = desenhada corretamente: { $line }
wrong-key-wrong = com o erro: { $line }
wrong-key-term = O termo que mais muda neste píxel: { $term } ({ $name }), com a luminância a passar de { $right } na imagem certa para { $wrong } na imagem com o erro.
wrong-key-normals = A normal do fragmento roda { $degrees }°.
share-too-long = a ligação tem { $length } caracteres; o phonglab lê no máximo { $most }
share-version = a ligação é da versão “{ $found }”; este phonglab lê a v{ $version }
share-damaged = a ligação está danificada: foi cortada ou alterada pelo caminho. Copie de novo a ligação inteira, do início ao último carácter
share-choice = a ligação pede algo que este phonglab não conhece: “{ $line }”
scene-link-refused = { $link }: { $why }
scene-link-empty = a ligação não contém nenhuma cena (a ligação de uma cena partilhada termina em #v1. e nos dados da cena): copie a ligação inteira
share-too-big = descomprimida, passa de { $most } bytes, mais do que o phonglab lê (mais do que qualquer cena que o phonglab escreve)
share-make-too-long = a ligação teria { $length } caracteres, e o phonglab abre ligações de no máximo { $most }: encurte o nome da cena
share-mesh-folders = a ligação nomeia a malha “{ $path }” com as suas pastas; uma ligação leva só o nome do ficheiro da malha, e o phonglab nunca lê um caminho que uma ligação nomeie: fica só o nome { $name } (abra esse ficheiro para a ver), e a esfera é mostrada até lá
mesh-missing-kept = A malha { $path } falta ou não pode ser lida ({ $error }); a cena fica e é mostrada na esfera. Abra a malha de novo para a ver.
shader = Programa de sombreamento (shader)

## names

doc-worksheet = a ficha, mview{ $k }
doc-worksheet-preset = Ficha, mview{ $k }

## presets

doc-phong-demo = a demo de Phong
doc-spotlight = um foco
doc-three-lights = três luzes coloridas e uma luz presa ao observador
doc-of-set-color = ofSetColor do openFrameworks com iluminação
doc-gouraud-misses-the-highlight = porque o Gouraud falha o brilho
doc-redbook-teapot = bules do Red Book: { $material }

## controls

specular-blinn-phong-normalised = Blinn-Phong normalizado (n.H)·(ns+8)/8π
ruleset-worksheet = Ficha de trabalho
ruleset-demo = Demo de Phong
pow-exact = pow exata
lights-count =
    { $count ->
    [one] { $count } luz
    *[other] { $count } luzes
    }
light-tab = Luz { $index }
light-ambient = Luz: ambiente
light-diffuse = Luz: difusa
light-specular = Luz: especular
attenuation-constant = Atenuação constante
attenuation-linear = Atenuação linear
attenuation-quadratic = Atenuação quadrática
spot-direction = Direção do foco
spot-cutoff = Abertura do foco (cutoff)
spot-exponent = Expoente do foco
material-ambient = Material: ambiente
material-diffuse = Material: difusa
material-specular = Material: especular
material-emission = Material: emissão
material-shininess = Material: brilho (ns)
quantity-vertex-position = Posição do vértice (espaço do objeto)
quantity-vertex-normal = Normal do vértice (espaço do objeto)
quantity-light-position = Posição da luz
quantity-material-alpha = Material: alfa
quantity-modelview = Matriz modelview
quantity-light-modelview = Modelview quando a luz foi colocada
scene-ambient = Ambiente da cena
local-viewer = Observador local
two-sided = Iluminação das duas faces
vertex = Vértice
normal = Normal
camera = Câmara
camera-kind-worksheet = Modelview da ficha
camera-kind-of = Câmara do openFrameworks
camera-kind-matrix = Matriz 4x4 escrita

## result

typed-empty = nenhum valor
typed-not-a-number = "{ $text }" não é um número
typed-not-finite = { $text } não é um número finito
typed-too-large = { $text } está além do alcance da precisão simples (±3,4e38)
typed-too-small = { $text } é pequeno demais para a precisão simples: seria 0

## explain

explain-heading = face { $side }, { $lights }, { $precision }, regras: { $rules }
side-front = da frente
side-back = de trás
note-line = nota: { $note }
step-normal = Vetor normal transformado
step-normal-back = Vetor normal transformado (face de trás: -N)
step-position = Vértice no espaço do olho
step-light-position = Luz no espaço do olho
step-l = Vetor da luz
step-distance = Distância à luz
step-v = Vetor do observador
step-ambient = Componente ambiente
step-diffuse = Componente difusa
step-h = Vetor médio
step-r = Vetor refletido
step-specular = Componente especular
step-attenuation = Atenuação
step-spot = Foco
step-share = Parte desta luz
step-scene-ambient = Ambiente da cena
step-emission = Emissão
step-primary = Cor do vértice
step-secondary = Cor secundária
step-clamped = Cor desenhada
note-color-material = GL_COLOR_MATERIAL ({ $mode }, { $face }): { $name } é a cor corrente (glColor) { $color }, e não o { $set } dado por glMaterial
formula-normal-gl = vertexNormal = (M^-1)^T · vertexNormal   (o N do OpenGL)
formula-normal-gl-normalize = vertexNormal = normalize((M^-1)^T · vertexNormal)   (o N do OpenGL, GL_NORMALIZE)
formula-normal-gl-rescale = vertexNormal = f · (M^-1)^T · vertexNormal, f = 1/|linha 3 de M^-1|   (o N do OpenGL, GL_RESCALE_NORMAL)
formula-normal-ws = vertexNormal = mview · vertexNormal   (a ficha: a própria M; OpenGL: (M^-1)^T)
formula-normal-ws-normalize = vertexNormal = normalize(mview · vertexNormal)   (a ficha: a própria M; OpenGL: (M^-1)^T)
formula-normal-ws-rescale = vertexNormal = f · mview · vertexNormal, f = 1/|linha 3 de M^-1|   (a M da ficha)
formula-position = vertexPos = mview · vertexPos, dividido por w   (OpenGL: P = M v)
formula-light-position = lightPos = mview · lightPos   (OpenGL: P_l, a modelview de quando a luz foi colocada vezes GL_POSITION)
formula-l-positional = vlv = normalize(lightPos − vertexPos)   (OpenGL: L = normalize(P_l − P))
formula-l-directional = vlv = normalize(lightPos)   (direcional, w = 0; OpenGL: L = normalize(P_l.xyz))
formula-v-local = vov = normalize(obs − vertexPos), obs = [0 0 0 1]   (observador local; OpenGL: V = −P/|P|)
formula-v-worksheet = vov = normalize(obs − vertexPos), obs = vertexPos · [1 1 0 1]   (o observador no infinito da ficha: (0, 0, −sinal z))
formula-v-infinite = vov = [0 0 1 0]   (observador no infinito; OpenGL: V = (0, 0, 1))
formula-r-demo = R = 2 max(vertexNormal · vlv, 0) vertexNormal − vlv   (o da demo)
gate-lit-side = f = 1 se cosTheta > 0, senão 0
gate-positive = f = 1 se { $cos } > 0, senão 0
gate-none = sem condição: f = 1 sempre
formula-specular = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns   ({ $gate }; f = { $f }; OpenGL: s_cl · s_cm · max(n · h, 0)^s_rm)
formula-specular-normalised = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns · (ns + 8)/(8π)   ({ $gate }; f = { $f }; Blinn-Phong que conserva a energia: quanto mais estreito o brilho, mais intenso, e a luz que reflete mantém-se; o OpenGL não tem este fator)
formula-at = at = atC + atLin · d + atQuad · d²   (OpenGL: as componentes são divididas por k0 + k1 d + k2 d²)
formula-at-directional = at = 1   (direcional)
formula-spot = spot = max(−L · s, 0)^e se −L · s >= cos(cutoff) = { $cutoff }, senão 0;  −L · s = { $angle }
formula-spot-none = spot = 1   (abertura de 180°: não é um foco)
formula-share-separate = Ilight = spot · (Iamb + Idif) / at   (a especular vai para a cor secundária)
formula-scene-ambient = a_cm a_cs   (ambiente do modelo de iluminação)
formula-i-opengl = I = e_cm + a_cm a_cs + soma das partes das luzes
formula-i-worksheet = I = (Iamb + Idif + Ispec) / at, somado sobre as luzes   (o I da ficha)
formula-secondary = soma de spot · Ispec / at   (especular separada)
formula-clamped = rgba limitado a [0, 1]; alfa = alfa da difusa
note-demo-space = a demo de Phong ilumina no espaço do objeto com o olho em (-4, 0, -8); aqui o espaço do olho é o espaço do objeto deslocado de (4, 0, 8), para que esse olho seja a origem: cada vetor e componente é o da demo
note-vov-behind = o texto da ficha diz que vov é sempre [0 0 1 0]; o seu código dá aqui [0 0 -1 0], porque o vértice está atrás do olho (z > 0)
note-no-distance = luz direcional: sem distância
mview-note-gap = por isso M n, a normal da ficha, aponta a { $angle } da (M^-1)^T n do OpenGL, e N e cada componente a seguir diferem dos do OpenGL
mview-note-small-gap = M n e a (M^-1)^T n do OpenGL apontam aqui a { $angle } uma da outra
mview-note-singular = M é singular: a (M^-1)^T n do OpenGL não existe
mview-note-rotation = M é uma rotação aos 6 algarismos com que está impressa (comprimentos das linhas { $lengths }); { $gap }
mview-note-rows = as linhas { $first } e { $second } fazem { $angle }
mview-note-rows-square = as suas linhas fazem 90°
mview-note-not-rotation = M não é uma rotação: { $rows } (as linhas de uma rotação fazem 90° e têm comprimento 1; estas têm comprimentos { $lengths }); { $gap }

## view

object-sphere = Esfera
object-teapot = Bule
object-cylinder = Cilindro
object-mesh = A sua malha
framing-orbit = Câmara em órbita
framing-clip = Espaço de recorte (o da demo)
fix-light-world = luz presa ao mundo
fix-true-normals = as normais verdadeiras da superfície
fix-highlight-colour = brilho da cor da luz
why-light-world = A demo ilumina posições e normais não transformadas, por isso a luz roda com o objeto; a correção do próprio documento transforma-as pela mvMatrix (para uma rotação, a inversa transposta é ela própria), e a luz fica parada enquanto o objeto roda.
why-true-normals = normalize(posição) só é a normal de uma esfera centrada na origem; as superfícies do bule e do cilindro apontam para outros lados, e as suas normais verdadeiras iluminam-nas como são.
why-highlight-colour = A demo multiplica a componente especular pelo vermelho do objeto; o OpenGL multiplica a cor especular da luz pela cor especular do material (aqui branca), por isso o brilho mostra a cor da luz.

## student-code

export-target-notebook = Caderno Jupyter (o da ficha)
export-target-pyopengl = Programa em Python (PyOpenGL + GLUT)
export-target-openframeworks = App openFrameworks (ofApp.h, ofApp.cpp, main.cpp)
export-target-glsl = Shaders GLSL
notebook-refused = o caderno não é escrito para esta cena: o explain toma aqui um limite ({ $reason }), e o NumPy do caderno imprimiria nan ou pararia; exporte-a como programa PyOpenGL, ou mude a cena
nb-title =
    # Cálculo da cor dos vértices com iluminação em OpenGL atual

    Cena: **{ $scene }**, escrita pelo phonglab (regras: { $rules }).

    obs: modifique os valores das variáveis de acordo com configuração que está a ser utilizada na app do OpenFrameworks; cada célula imprime o que o `phonglab explain` imprime, passo a passo.
nb-vertex =
    Inicialização do vértice a ser calculado:

    - tamanho da tela
    - pos (x, y, z, 1)
    - vetor normal (x, y, z, 0)
nb-light-material =
    Inicialização dos parâmetros da luz e material

    - posição/direção (x, y, z, 0/1)
    - luz l_ambiente, l_difusa, l_specular
    - luz atenuação_constante, atenuação_linear, atenuação_quadrática
    - luz spot direction, spot_cutoff, spot_coefficient
    - material k_ambiente, k_difusa, k_specular, shininess_ns
nb-settings = O que esta cena usa além da ficha (o phonglab escreveu as células seguintes para estas opções; para as mudar, mude a cena no phonglab e exporte de novo):
nb-modelview =
    Inicialização da matriz modelview

    o lookat vai transformar a matriz modelview, para fazer os cálculos precisaremos transformar os vetores e posições que utilizamos com a matriz modelview.
nb-light-mview-comment = # a posição de cada luz é transformada pela modelview que estava ativa quando se chamou glLight(GL_POSITION)
nb-color-material-comment = # GL_COLOR_MATERIAL ({ $mode }, { $face }): as cores do material que acompanha são a cor corrente, glColor = { $color }, e não as dadas por glMaterial
nb-vectors =
    Calcular os vetores necessários e normalizá-los:

    - normal do vértice
    - vetor luzPos - vérticePos (vlv)
    - vetor obsPos - vérticePos (vov)

    No caso da luz ser direcional, o vetor (luzPos-vérticePos) é desnecessário, usamos o próprio luzPos

    O vetor (obsPos - vérticePos) é calculado de forma diferente para `glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, true/false)`: quando **true**, obs = [0 0 0 1]; quando **false**, obs = (vertexPos) * [1 1 0 1], o vértice com o z a 0, e portanto vov = obs - vertexPos = [0 0 -z 0] antes de normalizado: só fica a componente z.

    A ficha diz de **false**: «vov vai sempre resultar em [0 0 1 0]». Só é assim para um vértice à frente do olho (z < 0 no espaço do olho): para um vértice atrás do olho (z > 0) esta fórmula dá [0 0 -1 0], e com z = 0 o vov não tem direção que se possa normalizar (0/0). (O observador no infinito do OpenGL é sempre V = (0, 0, 1).)

    mais info sobre isso em <https://registry.khronos.org/OpenGL-Refpages/gl2.1/xhtml/glLightModel.xml>
nb-normal-matrix-comment = # o OpenGL transforma as normais pela inversa transposta da 3x3 da modelview: (M^-1)^T n
nb-normal-as-is-comment = # a normal é usada tal como foi transformada (GL_NORMALIZE desligado): não é dividida pelo comprimento
nb-infinite-viewer-comment =
    #localViewer
    #false (OpenGL: o observador infinitamente longe ao longo de +z, V = (0, 0, 1))
nb-ambient =
    Cálculo da componente ambiente:

    - I<sub>amb</sub> = Luz<sub>amb</sub> × Material<sub>amb</sub>
nb-diffuse =
    Cálculo da componente difusa:

    - I<sub>dif</sub> = Luz<sub>dif</sub> × Material<sub>dif</sub> × cos(θ)
    - θ = ângulo entre normal e vetor(luzPos - verticePos)
    - θ ∈ [0°, 90°]
nb-acos-comment = # (cosTheta limitado a [-1, 1]: o arredondamento pode levar o produto interno de dois vetores unitários um pouco além de 1, onde o acos falha)
nb-specular-blinn =
    Cálculo da componente especular

    O modelo de Phong define o cálculo da componente especular como I<sub>spec</sub> = Luz<sub>spec</sub> × Material<sub>spec</sub> × cos(γ)<sup>ns</sup>, γ o ângulo entre o vetor saída da luz com a normal, e o observador.

    Contudo, a versão atual do OpenGL, utilizada no OpenFrameworks, utiliza uma variação do modelo de Phong para o cálculo da componente especular:

    - I<sub>spec</sub> = Luz<sub>spec</sub> × Material<sub>spec</sub> × cos(β)<sup>ns</sup>
    - β é o ângulo entre o vetor **halfway** do vetor (luz-pos) e (obs - pos), e a normal
    - β ∈ [0°, 90°]
    - H = (vlv + vov) / |vlv + vov|
nb-specular-phong =
    Cálculo da componente especular, modelo de Phong

    - I<sub>spec</sub> = Luz<sub>spec</sub> × Material<sub>spec</sub> × cos(α)<sup>ns</sup>
    - α é o ângulo entre R, o vetor da luz refletido na normal, e o observador
    - R = 2 (N · vlv) N - vlv
nb-gate-lit-side-comment = # OpenGL: sem especular de uma luz atrás da superfície (f = 0 onde N · L <= 0)
nb-specular-normalised =
    Blinn-Phong normalizado (que conserva a energia), como nos motores gráficos atuais: a componente é multiplicada por (ns + 8)/(8π), de modo que um brilho mais estreito (ns maior) é mais intenso e a luz que reflete se mantém aproximadamente a mesma. A iluminação de pipeline fixo do OpenGL não tem este fator.
nb-attenuation =
    Calculo da atenuação:

    - at = at<sub>constante</sub> + d × at<sub>linear</sub> + d² × at<sub>quadrática</sub>

    só vale para luz pontual ou foco!
nb-spot = O foco: dentro do cone (o ângulo entre -vlv e a direção do foco no máximo spotCutoff), spot = cos<sup>spotCoef</sup> desse ângulo; fora, 0; 1 para uma luz que não é foco (spotCutoff 180).
nb-final =
    Calculo final:

    - I<sub>final</sub> = (I<sub>amb</sub> + I<sub>dif</sub> + I<sub>spec</sub>)/at
nb-glcolor-comment = # a cor desenhada: limitada a [0, 1]; o alfa é o da cor difusa tal como o OpenGL a ilumina (1, ou matAlpha; o da cor atual quando GL_COLOR_MATERIAL segue a difusa), não matDif[3]: as cores acima estão escritas [r g b 0]
nb-back = A face de trás (iluminação das duas faces): os mesmos termos com a normal invertida (-vertexNormal) e o material de trás; os nomes acabam em Back.
nb-no-spot-comment = # não é um foco (spotCutoff 180)
import-unreadable = { $place }: não consigo ler `{ $line }`: { $reason }; ignorada
import-changed-in-place = altera um dado no próprio lugar (uma parte dele, ou com +=, *=, ...), o que o phonglab não segue: atribua o valor inteiro numa só linha
import-no-givens = isto não é um caderno nem um programa no estilo da ficha: não atribui nenhuma de vertexPos, vertexNormal, lightPos, matDif, mview
import-not-notebook = não é um caderno Jupyter: { $reason }
import-no-cells = não tem células
import-place-cell = célula { $cell }, linha { $line }
import-place-line = linha { $line }
import-reason-extra = `{ $token }` inesperado
import-reason-string = uma cadeia de caracteres não está fechada
import-reason-char = o carácter `{ $char }` não é compreendido
import-reason-expected = esperava `{ $token }`, encontrei `{ $found }`
import-reason-end = a expressão acaba cedo demais
import-reason-number = `{ $token }` não é um número
import-reason-name = `{ $name }` não é conhecido aqui (só se leem números, arrays e nomes atribuídos antes)
import-reason-arithmetic = `{ $op }` entre valores de formas diferentes
import-missing = { $name } não é atribuído: usa-se o valor da ficha, { $value }
import-malformed = { $place }: { $name } devia ser { $want }; usa-se o valor da ficha
import-want-vector = 4 números, [x, y, z, w]
import-want-number = um número
import-want-matrix = 4 linhas de 4 números
import-not-finite = { $place }: { $name } é { $value }, não um número finito; usa-se o valor da ficha
import-too-large = { $place }: `{ $line }` { $reason }: o ficheiro não é lido (os dados de uma ficha são alguns vetores pequenos)
import-limit-depth = aninha mais de { $depth } níveis
import-limit-elements = contém mais de { $count } números, cadeias e listas
import-limit-bytes = contém mais de { $count } bytes de cadeias
import-limit-tokens = tem mais de { $count } elementos léxicos (números, nomes, operadores e parênteses)
import-limit-total = leva os nomes atribuídos até aqui além do que o phonglab lê: { $limit }
bytes-described = { $count ->
        [one] { $bytes } byte
       *[other] { $bytes } bytes
    } ({ $scaled })
bytes-counted = { $count ->
        [one] { $bytes } byte
       *[other] { $bytes } bytes
    }
obj-index-not-number = linha { $line }: o índice de { $what } { $index } não é um número
obj-index-out-of-range = linha { $line }: o índice de { $what } { $index } está fora do intervalo (há { $count })
obj-what-vertex = vértice
obj-what-texture = textura
obj-what-normal = normal
obj-cannot-read-line = linha { $line }: não é possível ler: { $error }
obj-line-too-long = a linha { $line } tem mais de { $bytes } bytes: não é um ficheiro OBJ
obj-too-many-triangles = linha { $line }: mais de { $max } triângulos, o máximo que o phonglab sombreia
obj-not-a-number = linha { $line }: { $word } não é um número
obj-vertex-needs = linha { $line }: um vértice precisa de 3 números finitos
obj-normal-needs = linha { $line }: uma normal precisa de 3 números finitos
obj-face-needs = linha { $line }: uma face precisa de pelo menos 3 vértices
obj-no-faces = não há faces
obj-note-fanned = as faces de mais de 3 vértices (a primeira na linha { $line }) foram divididas em leque de triângulos
obj-note-normals = faces sem normais (a primeira na linha { $line }): as normais dos seus vértices foram calculadas como a média das normais das faces, pesada pela área
obj-note-fitted = centrada e escalada por { $scale } para caber na vista (raio 0,5)
obj-beyond-single = coordenadas fora do alcance da precisão simples: abra o ficheiro para as ajustar à vista
obj-cannot-read = não é possível ler { $path }: { $error }
obj-not-a-file = { $path } não é um ficheiro normal
obj-too-large = { $path } tem { $size }; o phonglab lê ficheiros OBJ de no máximo { $max } (cerca de { $millions } milhões de triângulos)
obj-over-budget = ler { $count ->
        [one] { $triangles } triângulo
       *[other] { $triangles } triângulos
    } ocupa { $bytes }, mais do que o orçamento de memória de { $budget } (--memory-budget aumenta-o)
export-flat-unsupported = o programa PyOpenGL desenha com os shaders gerados para a cena, que são Gouraud ou Phong: escolha um deles para a vista sombreada, não Flat
export-template-broken = o modelo de programa { $template } está mal preenchido ({ $problem }): é uma falha do phonglab; por favor comunique-a
py-title = { $scene }: a vista sombreada como o phonglab a desenha (sombreamento { $shading }), escrita pelo phonglab.
py-usage = Executar este ficheiro com python3 (uma janela; precisa de PyOpenGL, GLUT e NumPy). Com --png FICHEIRO desenha uma imagem de 512x512 (--size N: NxN), guarda-a em FICHEIRO e termina. O estado da iluminação é definido à maneira do pipeline fixo (glLightfv, glMaterialfv, glLightModel*), e os shaders abaixo calculam toda a iluminação do OpenGL 2.1 a partir desse estado, lido do GL em cada imagem: altere qualquer uma dessas chamadas e a imagem muda como mudaria no OpenGL de pipeline fixo, exceto onde um comentário junto à chamada diga o contrário.
py-rules-comment = O conjunto de regras para que os shaders foram escritos: "worksheet", "opengl" ou "phong-demo". Só a matriz das normais em set_uniforms() lê o RULES; o resto do conjunto de regras (incluindo a ambiente da cena e a emissão) são as linhas #define dos shaders.
py-shaders-comment = Os shaders: toda a iluminação do OpenGL 2.1 (por vértice em Gouraud, por fragmento em Phong), lendo o próprio estado do GL: gl_LightSource[], gl_FrontMaterial, gl_BackMaterial, gl_LightModel e os uniforms u_ que set_uniforms() lê com glGet*. Só as linhas #define são desta cena (os desvios do seu conjunto de regras em relação ao OpenGL); o `phonglab shader` imprime em vez disso os shaders especializados da cena.
py-projection-orbit = a câmara em órbita do phonglab: gluPerspective(40, 1, 0.1, 100)
py-projection-clip = nenhuma projeção: a imagem é o próprio espaço de recorte (o da demo de Phong)
py-modelview-comment = a modelview com que o objeto é desenhado: a câmara, depois a rotação do objeto (linhas)
py-lighting-modelview-comment = a modelview que a iluminação usa, onde não é a do desenho (a demo ilumina no espaço do objeto)
py-color-material-comment = GL_COLOR_MATERIAL: as cores do material que acompanha são a cor corrente (glColor); u_color é essa cor
py-normalised-comment = Blinn-Phong normalizado: a componente especular vezes (ns + 8)/(8π); o GL de pipeline fixo não tem este fator, por isso só o shader abaixo o calcula (a iluminação do próprio GL a partir deste estado não o faria)
py-light-eye = colocada sob a identidade: a luz move-se com o olho
py-light-object = colocada sob a modelview inteira: a luz roda com o objeto
py-light-world = colocada sob a matriz de vista: a luz fica parada no mundo
py-state-doc = O estado da iluminação da cena, definido à maneira do pipeline fixo. O GL_POSITION e o GL_SPOT_DIRECTION de cada luz são transformados pela modelview ativa quando são definidos, por isso o GL guarda-os no espaço do olho.
py-reader-doc = Dá aos shaders o que o GLSL não tem em variável nenhuma, lido do estado do GL em cada imagem: a modelview da iluminação e a matriz das normais, as luzes ligadas, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_COLOR_CONTROL, GL_NORMALIZE ou GL_RESCALE_NORMAL, GL_COLOR_MATERIAL e GL_SHADE_MODEL.
py-editable-comment = Pode alterar qualquer chamada abaixo (um valor de glLight*, glMaterial* ou glLightModel*, o glEnable ou glDisable de uma luz, GL_NORMALIZE, GL_COLOR_MATERIAL): os shaders leem este estado em cada imagem e desenham o que o OpenGL de pipeline fixo desenharia a partir dele, exceto onde um comentário abaixo diga o contrário. O RULES e as linhas #define dos shaders não são estado do GL: ficam como estão escritos.
py-lighting-comment = Os shaders iluminam o objeto quer GL_LIGHTING esteja ativo quer não: com glDisable(GL_LIGHTING), o OpenGL de pipeline fixo desenharia a cor atual (glColor) sem iluminação; estes shaders não.
py-scene-ambient-off = SCENE_AMBIENT é 0 com estas regras: os shaders não somam nem esta ambiente da cena nem a GL_EMISSION do material, por isso alterar qualquer uma delas aqui não muda nada (o OpenGL de pipeline fixo somaria as duas).
py-object-doc = O objeto, tal como o phonglab o constrói.
py-arrays-comment = os triângulos do phonglab (posições, normais e três índices de vértices por triângulo)
py-teapot-winding = o bule do freeglut tem os triângulos no sentido dos ponteiros do relógio: com iluminação das duas faces, o exterior seria iluminado como face de trás
of-header-comment = { $scene }: a sua iluminação numa app openFrameworks 0.12, escrita pelo phonglab. Assume o renderizador por omissão do oF: o ofSetupOpenGL abre uma janela GL 2.1, onde o ofGLRenderer ilumina com o OpenGL de pipeline fixo (não o renderizador programável do GL 3+).
of-main-comment = O renderizador por omissão: GL 2.1, iluminação de pipeline fixo (ver ofApp.h).
of-source-comment = As luzes, o material e a câmara da cena como o phonglab os tem; o oF coloca as luzes em coordenadas do mundo, só sob a vista da câmara.
of-camera-comment = a vista do phonglab: gluPerspective(40, 1, 0.1, 100) e a sua câmara em órbita
of-light-comment = a luz { $index } da cena
of-directional-comment = o GL_POSITION de uma luz direcional é a sua direção de olhar, w = 0
of-spot-comment = a direção do foco é a direção de olhar da luz
of-material-comment = o material, ativo enquanto o objeto é desenhado (ofSetColor com iluminação ligaria antes o glColorMaterial)
of-back-material-comment = o oF tem um material para as duas faces: o da face de trás, em GL direto
of-color-material-comment = GL_COLOR_MATERIAL: as cores do material que acompanha seguem a cor corrente, dada por ofSetColor
of-normalised-comment = Blinn-Phong normalizado: a componente especular vezes (ns + 8)/(8π); o GL de pipeline fixo não tem este fator, por isso a aplicação desenha com o shader gerado pelo phonglab (as luzes e o material do oF só definem o estado do GL)
of-shader-comment = os shaders gerais (toda a iluminação do OpenGL, lida do estado do GL), para o que o GL de pipeline fixo não calcula: só as suas linhas #define são o conjunto de regras desta cena; as luzes e o material são as chamadas de oF e de GL desta aplicação
of-shader-state-comment = o que o GLSL não tem em variável nenhuma, lido do estado do GL em cada imagem (os shaders leem eles próprios as luzes, o material e a ambiente da cena): altere qualquer chamada de luz, de material ou do modelo de iluminação e a imagem acompanha
of-no-scene-ambient = as regras desta cena não têm ambiente da cena: 0 aqui, para o GL calcular o mesmo I (o oF usa 0,2 por omissão)
of-rules-comment = o phonglab calcula esta cena com { $rules }; o GL de pipeline fixo calcula a equação do OpenGL, que pode diferir (a normal pela inversa transposta, a condição da especular)
of-phong-specular-comment = a especular desta cena é a de Phong (R · V); o GL de pipeline fixo calcula Blinn-Phong (N · H): o brilho difere
of-local-viewer-comment = o observador local: o oF não tem chamada para isso
of-two-sided-comment = iluminação das duas faces: o oF não tem chamada para isso
of-separate-specular-comment = uma cor especular separada: o oF não tem chamada para isso
of-normal-as-is-comment = o ofEnableLighting liga o GL_NORMALIZE; esta cena usa as normais tal como transformadas
of-normal-rescale-comment = o ofEnableLighting liga o GL_NORMALIZE; esta cena reescala as normais em vez disso
of-eye-light-comment = uma luz presa ao olho (uma lanterna de cabeça): o oF coloca as luzes no mundo, por isso GL direto sob a modelview identidade, na luz livre seguinte
of-spin-comment = a rotação do objeto na vista do phonglab
of-cylinder-comment = o gluCylinder vai ao longo de z; o cilindro do oF ao longo de y, centrado
of-no-teapot-comment = o oF não tem bule e aqui não lê ficheiros de malhas: uma esfera faz as vezes (carregue o seu modelo com ofMesh::load ou ofxAssimpModelLoader)
py-normal-matrix-comment = OpenGL: a inversa transposta da 3x3 da modelview; a ficha: a própria 3x3.

## compare

shader-step = passo { $n }
shader-note-directional-l = direcional: um só L para todos os vértices
shader-note-one-h = um só H: luz direcional, observador no infinito
shader-note-spot-cosine = cosseno do foco
shader-note-cone-test = o teste do cone
shader-note-alpha = alfa: o alfa difuso
shader-note-zero-normal = uma normal nula não tem direção: nem difusa, nem especular
shader-note-emission-ambient = emissão + ambiente da cena
shader-note-secondary = a cor secundária
shader-note-projective = a modelview é projetiva: dividir por w
shader-note-translation = a modelview é uma translação: a sua última coluna
shader-note-affine = modelview afim: w = 1, sem divisão
shader-note-normal-by-m = a ficha: a própria M
shader-header = phonglab: { $what }, sombreamento de { $shading }, gerado a partir do plano especializado.
    Só as etapas que a chave desta cena pede; os comentários dão os passos do cálculo.
shader-what-vertex-lighting = a iluminação por vértice
shader-what-program = O programa
shader-what-program-fragment = O programa por fragmento
shader-what-fragment-vertex-stage = a etapa de vértices da iluminação por fragmento
shader-what-fragment-lighting = a iluminação por fragmento
shader-vertex-shader = shader de vértices
shader-fragment-shader = shader de fragmentos

## sheets

exercise-modelview = rodar { $degrees } graus em torno de { $axis }, depois transladar { $translation }
exercise-name = exercício { $number } (semente { $seed })
sheet-rules-worksheet = as regras da ficha (sem ambiente da cena, sem emissão, a própria M para as normais)
sheet-rules-opengl = as regras da função fixa do OpenGL 2.1
sheet-rules-demo = as regras do shader da demo de Phong
sheet-compute = Calcule a cor do vértice passo a passo, segundo { $rules }.
sheet-colours = As cores escrevem-se como na ficha, [r g b 0], por isso cada produto de duas cores tem 0 como quarta componente.
sheet-vertex = O vértice
sheet-modelview = A modelview
sheet-direction = direção (w = 0)
sheet-position = posição
sheet-light-world = { $what }, em coordenadas do mundo: transforme-a pela modelview
sheet-degrees = { $value } graus
sheet-material = Material: { $name }
sheet-light-model = O modelo de iluminação
yes = sim
no = não
sheet-compute-heading = Calcular
exercise-effect-positional = uma luz pontual
exercise-effect-attenuation = atenuação
exercise-effect-spot = um foco
exercise-effect-local-viewer = o observador local
exercise-effect-two-sided = iluminação das duas faces
exercise-effect-several-lights = várias luzes

## moodle-exam

exam-modelview = rodar em torno de { $axis } pelo ângulo de cosseno { $cos } e seno { $sin }, depois transladar { $translation }
exam-name = exercício de exame { $number } (semente { $seed })
exam-material = escolhido para este exame
exam-no-calculator = Sem calculadora.
exam-by-hand = Todos os valores se calculam à mão e de forma exata: use cada um exato no passo seguinte e arredonde só o valor que escreve.
moodle-digits-quiz = Cada campo pede os algarismos significativos entre parênteses; uma resposta a menos de { $percent } % do valor (ou { $near_zero } perto de 0) está certa.
moodle-digits-exam = Indique cada valor arredondado a { $digits } algarismos significativos.
moodle-carry = Use cada valor no passo seguinte tal como o calculou, sem arredondar: arredonde só o que escreve num campo.
moodle-decimal-mark = Os números podem ser escritos com vírgula ou com ponto decimal: o Moodle aceita ambos.
moodle-part-digits = { $digits ->
    [one] um algarismo significativo
   *[other] { $digits } algarismos significativos
}
moodle-right = Certo: { $formula }
moodle-picture-feedback = A imagem da esquerda está desenhada com { $right }; a da direita com { $wrong }.
moodle-wrong = Não está certo. { $formula }; o que entra no cálculo: { $inputs }; verifique primeiro esses valores.
moodle-front-side = A iluminação é das duas faces: calcule a face da frente, aquela para onde aponta a normal do vértice (a de trás usa -n).
moodle-takes-givens = os dados
moodle-general-feedback = O feedback de cada campo dá a fórmula do seu passo; o cálculo completo de cada passo está na chave desta variante, que o professor tem.
moodle-picture-right = Desenhada corretamente
moodle-picture-wrong = Desenhada com um erro
moodle-picture-question = Que erro produz a imagem da direita?
moodle-choice-not = Não é este. Este erro mudaria a imagem de outra maneira: { $why }

## cli-out

channel-emission = Emissão
channel-scene-ambient = Ambiente da cena
channel-ambient = Ambiente
channel-diffuse = Difusa
channel-specular = Especular
channel-attenuation = 1/at (fator de atenuação)
channel-spot = Fator do foco
channel-n-dot-l = N·L
channel-n-dot-h = N·H
channel-r-dot-v = R·V
channel-normal = Normal como cor
channel-light-count = Luzes que chegam
probe-pixel = Píxel ({ $x }, { $y }), { $shading }
probe-triangle = triângulo { $triangle }, vértices { $a }, { $b }, { $c }
probe-front-face = face da frente (sentido anti-horário no ecrã)
probe-back-face = face de trás (sentido horário no ecrã)
probe-weights = Pesos corrigidos pela perspetiva
probe-vertex-colours = Cores dos vértices (cada uma limitada no seu vértice, como o OpenGL faz)
probe-vertex-colours-unclamped = Cores dos vértices (uma varying de shader: sem limitar)
probe-vertex = vértice { $vertex }
probe-weighted-sum = Soma pesada
probe-normal-interpolated = Normal interpolada, antes de normalizar
probe-normal-length = o seu comprimento
probe-normal = Normal com que o fragmento é iluminado
probe-normal-as-interpolated = Normal usada tal como interpolada (este shader não a normaliza)
probe-position = Posição interpolada (espaço do olho)
probe-flat-centroid = Face iluminada uma vez, no seu centroide (espaço do olho)
probe-flat-normal = com a normal do seu plano
probe-provoking = O GL_FLAT do OpenGL usaria a cor do último vértice, o vértice { $vertex }
probe-terms = Termos no píxel
probe-terms-interpolated = Termos no píxel (os dos vértices, interpolados)
probe-light = Luz { $index }
probe-terms-sum = Soma dos termos (sem limitar)
probe-unclamped = Cor que chegou ao framebuffer
probe-stored = Guardada, limitada e arredondada a 8 bits
probe-attenuation-factor = Fator de atenuação, pelo qual os termos são multiplicados

## io-errors

write-step-create-staging = criar uma pasta temporária em
write-step-list = listar
write-step-lock-folder = bloquear a pasta
write-step-recover = terminar o conjunto deixado por uma execução interrompida em
write-step-remove-journal = remover o diário de
write-step-killed = parar (morto) ao escrever
write-kept-folder = a pasta não mudou
write-kept-recoverable = o conjunto antigo ou o novo está completo, e a próxima execução nesta pasta termina o que foi começado
write-kept-staging = nada foi apagado: os ficheiros que não puderam voltar ao seu lugar ficaram na pasta de trabalho do phonglab lá dentro (.phonglab-set…), e a próxima execução nesta pasta repõe-nos ou diz onde estão

## errors

error-out-of-range = { $field } = { $value } está fora do intervalo: permitido { $allowed }
error-not-finite = { $field } tem de ser um número finito, não { $value }
error-too-many-lights = { $count } luzes: o OpenGL tem no máximo { $max }
error-camera-mismatch = a matriz de vista da cena não é a que a sua câmara dá ({ $camera }): defina a câmara, ou dê a matriz como câmara escrita
error-zero-attenuation = { $field }: as atenuações constante, linear e quadrática são todas 0, por isso a luz seria infinitamente brilhante; torna pelo menos uma positiva
allowed-spot-cutoff = [0, 90], ou 180 para não haver foco
allowed-float = um float: 0, ou 1,2e-38 <= |x| <= 3,4e38
allowed-mview = 1, 2, 3, 4 ou 5
allowed-look-at = um olho afastado do centro, com o vetor para cima fora da direção de vista
allowed-pixel = pelo menos 1 píxel
toml-place = linha { $line }, coluna { $column }
toml-unknown-field = campo desconhecido { $field }; os campos aceites são { $known }
toml-did-you-mean = queria dizer { $field }?
toml-missing-field = falta o campo { $field }
toml-invalid-type = tipo inválido: { $found }, esperava-se { $expected }
toml-kind-number = um número
toml-kind-number-value = o número { $value }
toml-kind-text = o texto { $value }
toml-kind-a-text = um texto (entre aspas)
toml-kind-boolean = true ou false
toml-camera-takes = { $field }: uma câmara do tipo kind = "{ $kind }" aceita { $keys }
toml-camera-needs = camera: kind = "{ $kind }" precisa de { $keys }
toml-unknown-material = { $field }: material desconhecido { $name }; os materiais clássicos são { $names }
toml-placement-needs-matrix = { $field }: placement = "matrix" precisa de placement_matrix (4 linhas de 4)
toml-matrix-needs-placement = { $field }: placement_matrix precisa de placement = "matrix"
toml-control-character = { $field } contém o carácter de controlo { $char } (carácter { $position }): um nome ou um caminho é uma linha de texto imprimível
toml-unknown-field-one = campo desconhecido { $field }; o campo aceite é { $known }

## limits

limit-light-at-vertex = a luz está no vértice: L não tem direção, por isso não há difusa nem especular; a sua componente ambiente fica, atenuada em d = 0
limit-light-direction-zero = a direção da luz direcional é (0, 0, 0): L não tem direção, por isso não há difusa nem especular; a sua componente ambiente fica
limit-halfway-zero = L é exatamente oposto a V, por isso H = L + V = 0 não tem direção: sem especular
limit-zero-normal = a normal é zero: sem difusa nem especular
limit-normal-scaled = |n|^2 sai do alcance desta precisão: n foi dividido pela sua maior componente antes de normalizar
limit-distance-scaled = |VP|^2 sai do alcance desta precisão: d foi calculado dividindo primeiro VP pela sua maior componente
limit-attenuation-infinite = k0 + k1 d + k2 d^2 = 0: as componentes da luz são +infinito onde positivas e 0 onde zero (o limite dá 1 e 0)
limit-spot-direction-zero = a direção do foco é (0, 0, 0): o cone não tem eixo, por isso o fator do foco é 0
limit-spot-at-vertex = o foco está no vértice: não há direção para comparar com o cone, por isso o fator do foco é 0
limit-vertex-at-eye = o vértice está no olho (observador local): V não tem direção, por isso não há especular
limit-vertex-at-infinity = o vértice tem w = 0 (um ponto no infinito): L aponta dele para as luzes pontuais, e d é infinito
limit-singular-modelview = a parte 3x3 da modelview é singular: as normais passam pela sua matriz dos cofatores, que só mantém a direção
limit-infinities-cancelled = uma componente infinita de um sinal encontrou outra do sinal oposto: a soma é indefinida e mostra-se 0

## cost

cost-approx-llvmpipe-pow = pow do llvmpipe
cost-approx-schlick-pow = pow de Schlick
cost-approx-fast-rsqrt = rsqrt rápida
cost-approx-no-renormalisation = sem renormalizar

## plan

effect-normalisation = normalização
effect-position = posição P no espaço do olho
effect-view-vector = vetor do observador V
effect-scene-colour = emissão e ambiente da cena
effect-back-side = face de trás
effect-light-vector = vetor da luz L e distância d
effect-attenuation = atenuação
effect-spotlight = foco
effect-halfway = vetor médio H
effect-reflection = vetor refletido R
effect-specular-power = potência especular
why-normalise-off = GL_NORMALIZE e GL_RESCALE_NORMAL estão desligados
why-rescale-one = GL_RESCALE_NORMAL está ligado mas o seu fator é exatamente 1 (a modelview preserva comprimentos)
why-normalize-on = GL_NORMALIZE está ligado
why-rescale-on = GL_RESCALE_NORMAL está ligado
why-renormalised = as normais interpoladas são renormalizadas
why-position-translation = P = p + t; a modelview é uma translação (a sua parte 3x3 é a identidade), por isso os produtos das linhas e a divisão por w são saltados: três somas
why-position-affine = P = M p; a modelview é afim (última linha 0 0 0 1), por isso w = 1 e a divisão por w é saltada
why-position-projective = P = M p / w: a modelview é projetiva, w varia de vértice para vértice
why-position-eye = os vértices chegam no espaço do olho: nada a transformar
why-position-unread = nenhuma luz pontual e V é uma constante (observador no infinito): nada lê P
why-v-local = observador local: V = normalize(-P) por vértice, em f64; um bloco de { $chunk } vértices cujas coordenadas estão todas entre 2^-400 e 2^400 salta a mudança de escala por potências de dois antes de elevar ao quadrado (aí não muda nenhum bit)
why-v-worksheet = o V da ficha = normalize(obs - P), obs = P (1, 1, 0, 1): (0, 0, -sinal(P.z)) por vértice
why-v-infinite = observador no infinito: V = (0, 0, 1) para todos os vértices
why-scene-added = somado como uma constante por face
why-scene-zero = ambos são zero (ou as regras deixam-nos de fora): nada é somado
why-two-sided = iluminação das duas faces: -n e o material do verso
why-one-sided = iluminação de uma face: a cor de trás é a da frente
why-l-positional = luz pontual: por vértice, em f64; um bloco de { $chunk } vértices cujas componentes de VP estão todas entre 2^-400 e 2^400 salta a mudança de escala por potências de dois antes de elevar ao quadrado (aí não muda nenhum bit)
why-l-directional = a luz é direcional: L é uma constante, não há d
why-attenuation-on = 1/(k0 + k1 d + k2 d^2) por vértice
why-attenuation-directional = a luz é direcional
why-attenuation-one = os fatores (1, 0, 0) dão 1
why-spot-on = teste do cone e expoente por vértice
why-spot-directional = a luz é direcional: o fator do foco é uma constante, calculada uma vez
why-spot-none = abertura de 180°: não é um foco
why-per-vertex = por vértice
why-h-constant = luz direcional e observador no infinito: H = normalize(L + V) é uma constante
why-specular-zero = especular da luz x especular do material é zero
why-power-on = max(cos, 0)^brilho por vértice
why-power-none = sem componente especular
why-power-zero = brilho 0: max(cos, 0)^0 = 1

## materials

material-name-emerald = esmeralda
material-name-jade = jade
material-name-obsidian = obsidiana
material-name-pearl = pérola
material-name-ruby = rubi
material-name-turquoise = turquesa
material-name-brass = latão
material-name-bronze = bronze
material-name-chrome = cromado
material-name-copper = cobre
material-name-gold = ouro
material-name-silver = prata
material-name-black-plastic = plástico preto
material-name-cyan-plastic = plástico ciano
material-name-green-plastic = plástico verde
material-name-red-plastic = plástico vermelho
material-name-white-plastic = plástico branco
material-name-yellow-plastic = plástico amarelo
material-name-black-rubber = borracha preta
material-name-cyan-rubber = borracha ciano
material-name-green-rubber = borracha verde
material-name-red-rubber = borracha vermelha
material-name-white-rubber = borracha branca
material-name-yellow-rubber = borracha amarela

## phonglab diagnose: a imagem de um aluno verificada

diagnose-normalize-off = GL_NORMALIZE deixado desligado com uma modelview que escala: as normais não têm comprimento 1
diagnose-viewer-swapped = O observador local e o observador no infinito trocados (GL_LIGHT_MODEL_LOCAL_VIEWER ao contrário)
diagnose-flipped-normals = As normais apontam para dentro (invertidas)
diagnose-two-sided-off = A iluminação das duas faces desligada: as faces de trás são iluminadas com as normais da frente
diagnose-two-sided-on = A iluminação das duas faces ligada onde a cena a tem desligada (GL_LIGHT_MODEL_TWO_SIDE verdadeiro): as faces de trás são iluminadas com as suas próprias normais e o material de trás, não com os da frente
diagnose-attenuation-left-out = A atenuação esquecida
diagnose-spot-left-out = O cone do foco esquecido (corte a 180)
# diagnose: picture mistakes
diagnose-shininess-fraction = O brilho dado como o valor de 0 a 1 de uma tabela de materiais em vez desse valor vezes 128 ({ $fraction } em vez de { $shininess-given }): um reflexo espalhado por todo o objeto
diagnose-light-left-out = A luz { $light } (GL_LIGHT{ $light }) esquecida: falta o glEnable(GL_LIGHT{ $light })
diagnose-point-as-directional = A luz { $light } (GL_LIGHT{ $light }) com w = 0 no GL_POSITION: uma luz direcional em vez de uma luz pontual
diagnose-light-ambient-left-out = A cor ambiente da luz { $light } (GL_LIGHT{ $light }) deixada no valor por omissão do OpenGL (0, 0, 0, 1)
diagnose-specular-left-out = A cor especular do material deixada no valor por omissão do OpenGL (0, 0, 0, 1): sem reflexo
diagnose-diffuse-specular-swapped = As cores difusa e especular do material trocadas
diagnose-emission-added = Uma cor constante, cerca de { $emission }, somada onde o objeto está iluminado ou não: uma emissão (GL_EMISSION) que a cena não tem, ou mais luz ambiente
diagnose-colours-differ = As cores da imagem são as de outros valores (em cada termo, a cor da luz vezes a do material): { $terms }
diagnose-term-scene = a luz igual em todo o lado (a ambiente da cena e a ambiente de cada luz sem atenuação nem foco, vezes o ambiente do material, mais a emissão)
diagnose-term-ambient = a ambiente de GL_LIGHT{ $light }
diagnose-term-diffuse = a difusa de GL_LIGHT{ $light }
diagnose-term-specular = a especular de GL_LIGHT{ $light }
diagnose-term-differs = { $term }: { $shown } na imagem, { $scene } na cena
diagnose-materials-differ = Os materiais da imagem têm outras cores que os da cena numa das faces (iluminação das duas faces, cada face com o seu material): { $colours }
diagnose-side-front = da frente
diagnose-side-back = de trás
diagnose-material-colour-differs = { $name } { $which }: { $shown } na imagem, { $scene } na cena
diagnose-material-shininess-differs = GL_SHININESS { $which }: { $shown } na imagem, { $scene } na cena
diagnose-spot-cutoff-doubled = O corte do foco da luz { $light } (GL_LIGHT{ $light }) dobrado: foi dado o ângulo total do cone onde GL_SPOT_CUTOFF recebe metade dele
diagnose-normal-matrix-not-transposed = As normais transformadas pela inversa da 3x3 da modelview (np.linalg.inv(m3)) onde o OpenGL usa a inversa transposta: sob uma rotação rodam para o lado errado
diagnose-normal-not-transformed = As normais deixadas no espaço do objeto (sem a matriz das normais da modelview): o objeto é iluminado como se não tivesse rodado
diagnose-depth-test-off = O teste de profundidade ficou de fora (falta glEnable(GL_DEPTH_TEST)): cada triângulo cobre os desenhados antes dele, por isso o lado de trás do objeto aparece por cima do da frente onde é desenhado depois
diagnose-quadric-inside = A quádrica virada do avesso (gluQuadricOrientation(GLU_INSIDE)): as normais apontam para dentro e as faces viram-se para dentro, por isso o lado iluminado fica do lado contrário ao da luz
diagnose-light-after-model-light = A luz { $light } (GL_LIGHT{ $light }) dada com a matriz modelview com que o objeto é desenhado (vista × modelo) em vez da sua: move-se com o objeto
diagnose-spot-cutoff-differs = O corte do foco da luz { $light } (GL_LIGHT{ $light }, GL_SPOT_CUTOFF) parece ser { $cutoff }° na imagem; a cena dá { $cutoff-scene }°
diagnose-spot-exponent-differs = O expoente do foco da luz { $light } (GL_LIGHT{ $light }, GL_SPOT_EXPONENT) parece ser { $exponent } na imagem; a cena dá { $exponent-scene }
diagnose-attenuation-constant-differs = A atenuação constante da luz { $light } (GL_LIGHT{ $light }, GL_CONSTANT_ATTENUATION) parece ser { $constant } na imagem; a cena dá { $constant-scene }
diagnose-attenuation-linear-differs = A atenuação linear da luz { $light } (GL_LIGHT{ $light }, GL_LINEAR_ATTENUATION) parece ser { $linear } na imagem; a cena dá { $linear-scene }
diagnose-attenuation-quadratic-differs = A atenuação quadrática da luz { $light } (GL_LIGHT{ $light }, GL_QUADRATIC_ATTENUATION) parece ser { $quadratic } na imagem; a cena dá { $quadratic-scene }
diagnose-shininess-differs = O brilho (GL_SHININESS) parece ser { $shininess } na imagem; a cena dá { $shininess-scene }
diagnose-value-negligible = { $least } ou mais (a luz é desprezável: nada dela chega ao objeto)
diagnose-attenuation-left-out-light = A atenuação da luz { $light } (GL_LIGHT{ $light }) esquecida
diagnose-spot-direction-untransformed = A direção do foco da luz { $light } (GL_LIGHT{ $light }) dada antes da transformação da câmara (com a identidade), e a sua posição depois dela
diagnose-light-after-model = As luzes colocadas no mundo dadas depois da transformação de modelo (com vista × modelo em vez da vista): rodam com o objeto
diagnose-headlight-under-view = A luz { $light } (GL_LIGHT{ $light }), fixa ao olho, dada com a transformação de vista em vez da identidade: fica colocada no mundo
diagnose-light-before-view-light = A luz { $light } (GL_LIGHT{ $light }) colocada antes da câmara: o seu GL_POSITION dado com a identidade e não com a transformação de vista, por isso move-se com o olho
diagnose-colour-material-off = GL_COLOR_MATERIAL não ativado: o objeto é iluminado com as cores do glMaterial, não com a cor corrente
diagnose-colour-material-diffuse-only = O glColorMaterial a seguir só GL_DIFFUSE em vez de GL_AMBIENT_AND_DIFFUSE: a cor ambiente fica a do glMaterial
diagnose-spot-cutoff-halved = O corte do foco da luz { $light } (GL_LIGHT{ $light }) reduzido a metade: foi dado o ângulo total do cone onde GL_SPOT_CUTOFF recebe metade dele
diagnose-spot-cutoff-radians = O corte do foco da luz { $light } (GL_LIGHT{ $light }) dado em radianos (math.radians): o OpenGL recebe GL_SPOT_CUTOFF em graus
diagnose-spot-exponent-ignored = O expoente do foco da luz { $light } (GL_LIGHT{ $light }) esquecido (0): um círculo de luz de bordo nítido
diagnose-spot-cutoff-exponent-swapped = O corte e o expoente do foco da luz { $light } (GL_LIGHT{ $light }) trocados
diagnose-spot-direction-reversed = A direção do foco da luz { $light } (GL_LIGHT{ $light }) invertida: aponta do alvo para a luz
diagnose-attenuation-terms-swapped = As atenuações linear e quadrática da luz { $light } (GL_LIGHT{ $light }) trocadas
diagnose-attenuation-constant-left-out = A atenuação constante da luz { $light } (GL_LIGHT{ $light }) posta a 0 (como se 0 significasse sem atenuação)
diagnose-directional-as-point = A luz { $light } (GL_LIGHT{ $light }) com w = 1 no GL_POSITION: uma luz pontual em vez de uma luz direcional
diagnose-diffuse-back-only = A cor difusa do material dada só para GL_BACK: as faces da frente ficam com o valor por omissão do OpenGL (0,8, 0,8, 0,8)
diagnose-ambient-back-only = A cor ambiente do material dada só para GL_BACK: as faces da frente ficam com o valor por omissão do OpenGL (0,2, 0,2, 0,2)
diagnose-specular-back-only = A cor especular e o brilho do material dados só para GL_BACK: as faces da frente ficam com os valores por omissão do OpenGL (sem reflexo)
diagnose-material-back-only = Todas as chamadas glMaterial dadas só para GL_BACK: as faces da frente ficam com o material por omissão do OpenGL
diagnose-light-colour-0-255 = A cor difusa da luz { $light } (GL_LIGHT{ $light }) dada de 0 a 255 em vez de 0 a 1
diagnose-row-vectors = A matriz de modelação e vista das luzes carregada transposta (as linhas do NumPy dadas ao glLoadMatrixf como colunas)
diagnose-light-ambient-from-diffuse = A cor ambiente da luz { $light } (GL_LIGHT{ $light }) copiada da sua cor difusa
diagnose-ambient-from-diffuse = A cor ambiente do material igual à sua cor difusa (GL_AMBIENT_AND_DIFFUSE)
diagnose-specular-from-colour = A cor especular do material igual à cor do objeto: um reflexo colorido
diagnose-emission-left-out = A emissão do material deixada a preto (0, 0, 0, 1)
diagnose-row-vectors-light = A matriz de modelação e vista da luz { $light } (GL_LIGHT{ $light }) carregada transposta (as linhas do NumPy dadas ao glLoadMatrixf como colunas)
diagnose-emission-from-colour = A emissão do material igual à cor do objeto: o objeto brilha com a sua própria cor
diagnose-ambient-diffuse-swapped = As cores ambiente e difusa do material trocadas
diagnose-light-diffuse-left-out = A cor difusa da luz { $light } (GL_LIGHT{ $light }) nunca definida: o valor por omissão do OpenGL, branco para GL_LIGHT0 e preto para as outras
diagnose-diffuse-not-clamped = No shader, o termo difuso usa N·L sem max(N·L, 0): onde a luz está atrás da superfície, subtrai luz
diagnose-vlv-reversed = No shader, o vetor da luz L aponta da luz para a superfície (P − posição da luz) em vez de apontar da superfície para a luz
diagnose-viewer-reversed = No shader, o V do observador local aponta do olho para o ponto (normalize(P)) em vez de apontar para o olho (normalize(−P))
diagnose-halfway-not-normalised = No shader, o vetor médio L + V não é normalizado antes do produto escalar com N
diagnose-flat-shade-model = glShadeModel(GL_FLAT) em vez de GL_SMOOTH: cada face tem uma só cor, a cor calculada no seu último vértice
diagnose-view-order-reversed = A modelview do objeto multiplicada pela ordem errada (rotação × translação em vez de translação × rotação): o objeto é desenhado e iluminado fora do seu lugar
diagnose-view-order-reversed-lights = A matriz de vista multiplicada pela ordem errada (rotação × translação em vez de translação × rotação), para o objeto e para as luzes colocadas com ela
diagnose-view-order-reversed-lights-only = A matriz de vista das luzes multiplicada pela ordem errada (rotação × translação em vez de translação × rotação): as luzes colocadas no mundo ficam no sítio errado; o objeto é desenhado bem
diagnose-shininess-refused = GL_SHININESS dado acima de 128 (um valor de 0 a 1 multiplicado por 128 duas vezes, ou numa escala de 0 a 1000): o OpenGL recusa a chamada (GL_INVALID_VALUE) e o brilho fica no valor por omissão, 0: a cor especular espalhada por todo o lado iluminado
diagnose-directional-reversed = A direção da luz { $light } (GL_LIGHT{ $light }) invertida: o GL_POSITION (x, y, z, 0) dado como a direção em que a luz segue em vez da direção que aponta para a luz, por isso o objeto é iluminado do lado oposto
diagnose-scene-ambient-default = A luz ambiente da cena (glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ...)) nunca definida: o valor por omissão do OpenGL (0,2, 0,2, 0,2, 1)
diagnose-light-specular-left-out = A cor especular da luz { $light } (GL_LIGHT{ $light }) nunca definida: o valor por omissão do OpenGL, branco para GL_LIGHT0 e preto para as outras
diagnose-light-ambient-diffuse-swapped = As cores ambiente e difusa da luz { $light } (GL_LIGHT{ $light }) trocadas
diagnose-light-diffuse-on-previous = A cor difusa da luz { $light } dada a GL_LIGHT{ $previous } (um bloco copiado em que o número da luz não foi mudado): GL_LIGHT{ $previous } fica com ela e GL_LIGHT{ $light } fica com o valor por omissão do OpenGL
diagnose-light-specular-on-previous = A cor especular da luz { $light } dada a GL_LIGHT{ $previous } (um bloco copiado em que o número da luz não foi mudado): GL_LIGHT{ $previous } fica com ela e GL_LIGHT{ $light } fica com o valor por omissão do OpenGL
diagnose-positions-as-normals = As posições dos vértices dadas como normais (glNormal3fv(posição)): cada normal aponta a partir do centro do objeto e tem por comprimento a distância do ponto (o raio, numa esfera), o que o ilumina mal sem GL_NORMALIZE
diagnose-colour-material-ambient-and-diffuse = O glColorMaterial a seguir GL_AMBIENT_AND_DIFFUSE em vez de só GL_DIFFUSE: a cor corrente substitui também a cor ambiente do material
diagnose-colour-material-wrong-face = O glColorMaterial dado para a face errada (GL_BACK em vez de GL_FRONT, ou o contrário): as faces que se veem ficam com as cores do glMaterial em vez da cor corrente
diagnose-spot-cutoff-cosine = O corte do foco da luz { $light } (GL_LIGHT{ $light }) dado como o seu cosseno (math.cos(math.radians(…)), cerca de 0,99): o OpenGL recebe GL_SPOT_CUTOFF em graus, por isso o cone tem menos de um grau
diagnose-material-front-only = Iluminação das duas faces com as chamadas glMaterial dadas só para GL_FRONT: as faces de trás ficam com o material por omissão do OpenGL
diagnose-emission-back-only = A emissão do material dada só para GL_BACK: as faces da frente ficam com o valor por omissão do OpenGL, preto
diagnose-material-diffuse-0-255 = A cor difusa do material dada de 0 a 255 em vez de 0 a 1 ({ $diffuse-levels } em vez de { $diffuse-given }): o termo difuso satura onde quer que a luz chegue
diagnose-material-colours-0-255 = As cores do material (ambiente, difusa, especular) dadas de 0 a 255 em vez de 0 a 1: o objeto satura
diagnose-light-not-normalised = No shader, o L de uma luz pontual não é normalizado (L = luz − P sem dividir pelo seu comprimento d): N·L e o cosseno do foco crescem com a distância
diagnose-reflection-reversed = No shader, R refletido ao contrário (reflect(L, N) em vez de reflect(-L, N)): o reflexo aparece do lado oposto àquele onde devia estar
diagnose-rescale-for-normalize = GL_RESCALE_NORMAL ativado onde é preciso GL_NORMALIZE: com uma escala não uniforme as normais são reescaladas mas não ficam com comprimento 1
diagnose-same-picture = Estas causas desenham a mesma imagem, por isso ela não permite distingui-las (as mais comuns primeiro): { $ids }. Verifique qual delas está no programa.
diagnose-same-picture-fitted = Estas causas desenham a mesma imagem, por isso ela não permite distingui-las (as mais comuns primeiro, um valor alterado antes de um valor ajustado à imagem): { $ids }. Verifique qual delas está no programa.
diagnose-light-unseen = Nada da luz { $light } (GL_LIGHT{ $light }) chega ao objeto: a imagem é a cena iluminada sem ela.
diagnose-nothing-drawn = nada do objeto está desenhado: a imagem é só o fundo. Verifique a chamada que o desenha (glutSolidTeapot, gluSphere…) e que ela corre, e a câmara (gluLookAt, gluPerspective): o objeto pode estar atrás dela ou fora do seu campo de visão.
diagnose-outline-differs = o contorno do objeto não é o desta cena ({ $share } dele difere, para além de um píxel): é esta a imagem desta cena? Verifique --scene, e o objeto e a câmara do programa.
diagnose-region-differs = uma região de { $pixels } píxeis em torno de ({ $x }, { $y }) difere da imagem certa (a imagem certa explica { $score } dos píxeis do objeto): há algo desenhado por cima do objeto ali, ou essa parte dele está errada. Verifique o que o programa desenha depois do objeto, e a iluminação dessa parte (as suas normais, o seu material).
diagnose-offset-darker = os { $pixels } píxeis do objeto de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 }) estão uniformemente mais escuros do que na imagem certa, { $levels } níveis em média (o ruído, uma gravação com perdas ou um píxel de desvio deixam menos de { $least }) (a imagem certa explica { $score } dos píxeis do objeto): algo foi pintado sobre o objeto aí, ou a sua luz ou o seu material estão ligeiramente errados. Verifique o que o programa desenha depois do objeto e compare os valores de glLight*/glMaterial* do programa com os da cena.
diagnose-offset-lighter = os { $pixels } píxeis do objeto de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 }) estão uniformemente mais claros do que na imagem certa, { $levels } níveis em média (o ruído, uma gravação com perdas ou um píxel de desvio deixam menos de { $least }) (a imagem certa explica { $score } dos píxeis do objeto): algo foi pintado sobre o objeto aí, ou a sua luz ou o seu material estão ligeiramente errados. Verifique o que o programa desenha depois do objeto e compare os valores de glLight*/glMaterial* do programa com os da cena.
diagnose-marks-differ = marcas finas de { $pixels } píxeis, de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 }), diferem da imagem certa (a imagem certa explica { $score } dos píxeis do objeto): há linhas ou marcas desenhadas por cima do objeto ali. Verifique o que o programa desenha depois do objeto (texto, eixos, um cursor), e guarde o seu PNG antes de se desenhar algo por cima.
diagnose-levels-darker = a imagem inteira está, em média, { $levels } níveis mais escura do que a certa, e a imagem certa com os níveis assim mudados explica-a tão bem como qualquer erro ({ $score } dos píxeis do objeto). Uma mudança do gama, do brilho ou do perfil de cor da imagem guardada faz isto, e um erro na iluminação pode esconder-se por baixo: guarde o PNG do programa sem o alterar (com a opção --png) e verifique-o de novo.
diagnose-levels-lighter = a imagem inteira está, em média, { $levels } níveis mais clara do que a certa, e a imagem certa com os níveis assim mudados explica-a tão bem como qualquer erro ({ $score } dos píxeis do objeto). Uma mudança do gama, do brilho ou do perfil de cor da imagem guardada faz isto, e um erro na iluminação pode esconder-se por baixo: guarde o PNG do programa sem o alterar (com a opção --png) e verifique-o de novo.
diagnose-footprint = Este erro altera a imagem certa em { $most } níveis, no máximo; em mais de { $tolerance } níveis, além do deslocamento de um píxel, apenas em { $pixels } píxeis: { $groups }. São demasiado poucos para a percentagem o mostrar; ali a sua imagem é a do erro: está, em média, a { $mistake } níveis da imagem com o erro e a { $right } da imagem certa.
diagnose-footprint-group = { $count } de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 })
diagnose-footprint-rest = { $count } noutros sítios
diagnose-footprint-and = e
diagnose-verdict-right-lossy = Certa, com perdas: a imagem certa explica { $score } dos píxeis do objeto a menos de { $levels } níveis de uma mistura dos seus vizinhos ({ $strict } a menos de { $tolerance } de um vizinho), e o que difere é ruído (como o deixado por um JPEG, um redimensionamento, uma desfocagem ou uma câmara), não uma alteração que a imagem mostre. Um valor ligeiramente errado (um expoente do foco 9 em vez de 8) pode esconder-se nas perdas; os números que o programa imprime mostram-no (phonglab check).
diagnose-looks-jpeg = A imagem parece ter sido guardada como JPEG: a sua diferença para a imagem certa salta nas margens de blocos de 8 x 8 ({ $ratio } vezes mais do que dentro deles). Guardar com perdas muda um pouco cada píxel e pode esconder a causa: guarde a imagem como PNG diretamente do programa (com a opção --png do programa exportado) e diagnostique essa.
diagnose-evenly-off = A imagem não é a certa apenas com perdas: nos { $width } x { $width } píxeis a partir de ({ $x0 }, { $y0 }) o seu { $channel ->
        [0] vermelho
        [1] verde
       *[2] azul
    } difere do da imagem certa { $levels } níveis em média, { $errors } erros-padrão além do que um desvio de meio píxel faz aí; o ruído e uma gravação com perdas espalham essa média à volta de 0. Um valor da cena (uma cor, uma atenuação, o brilho) pode estar um pouco errado aí, ou a imagem deslocada mais de meio píxel, e as perdas podem esconder qual: guarde a imagem como PNG diretamente do programa (com a opção --png do programa exportado) e diagnostique essa.
diagnose-verdict-right-within = Certa, tanto quanto uma imagem permite dizer: a imagem certa explica { $score } dos píxeis do objeto (com um píxel de desvio e { $tolerance } níveis de tolerância), mas dentro do objeto a sua imagem difere dela até { $most } níveis, { $pixels } píxeis em mais de { $rounding }. Um erro que não altere a imagem mais do que isso (um brilho ou uma cor ligeiramente diferentes) tem o mesmo aspeto: este veredicto não o exclui. Os números do programa excluem-no: verifique os valores que o caderno imprime com o phonglab check, ou compare os valores de glLight*/glMaterial* do programa com os da cena.
diagnose-verdict-right = Certa: a imagem certa explica { $score } dos píxeis do objeto e, dentro do objeto, a sua é essa imagem até ao arredondamento ({ $rounding } nível), como outro OpenGL a desenha. Um valor tão pouco errado que não mude nenhum píxel mais do que isso não se vê numa imagem; os números que o programa imprime mostram-no (phonglab check).
diagnose-verdict-wrong = Errada. A causa: { $cause } ({ $id }); a imagem com esse erro explica { $score } dos píxeis do objeto, a imagem certa { $right }.
diagnose-verdict-wrong-nearer = Errada. A causa: { $cause } ({ $id }). A imagem com esse erro e a imagem certa explicam ambas { $score } dos píxeis do objeto dentro da tolerância, mas onde as duas diferem ({ $pixels } píxeis) a sua está, em média (quadrática), a { $fitted } níveis da primeira e a { $scene } da certa.
diagnose-verdict-wrong-nearer-inside = Errada. A causa: { $cause } ({ $id }). A imagem com esse erro e a imagem certa explicam ambas { $score } dos píxeis do objeto dentro da tolerância, mas dentro do objeto a sua está, em média, a { $fitted } níveis da primeira (somados os três canais) e a { $scene } da certa.
diagnose-verdict-wrong-or = Errada. A causa: { $cause } ({ $id }) ou { $other } ({ $other-id }){ $more ->
        [0] {""}
        [one] , ou mais uma, listada abaixo
       *[other] , ou uma de mais { $more }, listadas abaixo
    }: a imagem não permite dizer qual; cada um destes erros explica { $score } dos píxeis do objeto, a imagem certa { $right }.
diagnose-unexplained-said = Não explicada: { $finding }
diagnose-difference-said = |A − B| de cada canal × { $gain }: preto onde as duas imagens coincidem, intensidade máxima (255) a partir de uma diferença de { $full } { $full ->
        [one] nível
       *[other] níveis
    }; a maior diferença aqui, { $largest } { $largest ->
        [one] nível
       *[other] níveis
    }, está desenhada a { $drawn }/255{ $boxes ->
        [0] .
        [one] . Uma caixa tracejada a magenta marca o sítio que o diagnóstico indica.
       *[other] . Caixas tracejadas a magenta marcam os { $boxes } sítios que o diagnóstico indica.
    }
diagnose-also = Também explica a imagem: { $cause } ({ $id }), { $score }.
diagnose-verdict-unexplained = Nenhum erro que o phonglab conheça explica esta imagem: a imagem certa explica { $right } dos píxeis do objeto. O erro mais próximo, que não é dado como a causa ({ $id }, { $score }): { $cause }.
diagnose-verdict-unexplained-none = Nenhum erro que o phonglab conheça explica esta imagem: a imagem certa explica { $right } dos píxeis do objeto.
diagnose-where = Os píxeis contam-se a partir de (0, 0) no canto superior esquerdo, com y para baixo, como as linhas do PNG (o glReadPixels conta a partir do canto inferior esquerdo).

## phonglab check: o trabalho de um aluno verificado

check-no-outputs = este caderno foi guardado sem os resultados: não há nada impresso para verificar. Execute-o primeiro (Jupyter: Kernel → Restart & Run All), guarde-o e verifique-o de novo
check-too-many-values = este trabalho imprime mais de { $count } números: é recusado por inteiro em vez de verificado só em parte (imprima só os passos da ficha)
check-verdict-right = certo
check-verdict-right-given = certo, dado o seu { $step }
check-verdict-rounding = arredondamento
check-verdict-wrong = errado
check-cause-normal-by-modelview = a normal transformada pela modelview M em vez da sua inversa transposta (errado com uma escala não uniforme)
check-cause-normal-not-normalised = a normal não normalizada depois de transformada
check-cause-light-not-transformed = a posição da luz não transformada pela modelview (ficou no espaço do objeto)
check-cause-light-transformed-twice = a posição da luz transformada duas vezes pela modelview
check-cause-vectors-cell-run-twice = a normal parece transformada duas vezes, e o vértice e a luz com ela: a célula que os transforma foi executada duas vezes. Reinicie e execute tudo (Jupyter: Kernel → Restart & Run All)
check-cause-vlv-reversed = vlv ao contrário: da luz para o vértice em vez do vértice para a luz
check-cause-vlv-not-normalised = vlv não normalizado
check-cause-directional-as-point = uma luz direcional (w = 0) tratada como pontual
check-cause-viewer-swapped = o observador local e o observador no infinito trocados
check-cause-halfway-not-normalised = H não normalizado
check-cause-specular-without-gate = especular calculada onde a luz está atrás da superfície (falta a condição N·L)
check-cause-diffuse-not-clamped = a difusa não limitada: negativa quando o ângulo passa os 90 graus
check-cause-acos-past-one = acos de um cosseno ligeiramente acima de 1 (arredondamento): limite-o primeiro a [-1, 1]
check-cause-spot-cutoff-radians = o cosseno do ângulo de corte do foco calculado em graus como se fossem radianos
check-cause-spot-exponent-outside-cone = o expoente do foco aplicado também fora do cone
check-cause-attenuation-multiplied = a luz multiplicada pela atenuação em vez de dividida
check-cause-attenuation-object-distance = a distância da atenuação medida no espaço do objeto
check-cause-w-divide-forgotten = falta a divisão por w
check-cause-shininess-fraction = o brilho como fração de 0 a 1 em vez de multiplicado por 128
check-cause-for-light = { $cause } (luz { $light })
check-cause-normal-matrix-with-translation = a normal transformada pela inversa transposta da modelview 4x4 inteira: a translação dá à normal um w que entra no seu comprimento
check-cause-normal-not-transformed = a normal não transformada para o espaço do olho
check-cause-vertex-not-transformed = a posição do vértice não transformada pela modelview (ficou no espaço do objeto)
check-cause-point-as-directional = uma luz pontual tratada como direcional: vlv tirado só da sua posição
check-cause-viewer-reversed = vov ao contrário: do olho para o vértice em vez do vértice para o olho
check-cause-light-ambient-left-out = falta o termo ambiente da luz na sua contribuição
check-cause-ambient-times-cosine = o termo ambiente multiplicado por N·L como a difusa (a luz ambiente não tem direção)
check-cause-colours-mixed-up = uma cor do termo errado (ou nenhuma) num produto: cada termo multiplica a cor da luz e a do material desse mesmo termo
check-cause-cos-theta-with-light-position = cosTheta calculado com a posição da luz em vez do vetor unitário vlv
check-cause-theta-in-degrees = o ângulo convertido para graus e comparado com pi/2 (radianos): a difusa desaparece acima de 1,57 graus
check-cause-reflection-for-halfway = o R·V de Phong usado onde o OpenGL usa o N·H de Blinn-Phong
check-cause-reflection-reversed = R ao contrário: L - 2(N·L)N em vez de 2(N·L)N - L
check-cause-specular-cosine-not-clamped = o cosseno especular não limitado a 0 antes da potência
check-cause-specular-left-out = falta o termo especular na contribuição da luz
check-cause-attenuation-left-out = a contribuição da luz não dividida pela atenuação
check-cause-ambient-not-attenuated = o termo ambiente da luz não dividido pela atenuação (o OpenGL atenua o ambiente, a difusa e a especular da mesma forma)
check-cause-attenuation-constant-left-out = falta o termo constante da atenuação
check-cause-attenuation-quadratic-not-squared = o termo quadrático da atenuação multiplicado por d em vez de d²
check-cause-distance-from-normalised-vlv = a distância tirada do vlv já normalizado (sempre 1)
check-cause-distance-squared = a distância ao quadrado: falta a raiz quadrada
check-cause-spot-exponent-ignored = falta o expoente do foco: o fator do foco é o próprio cosseno
check-cause-cone-test-inverted = o teste do cone do foco ao contrário: iluminado fora do cone, escuro dentro
check-cause-spot-angle-reversed = o ângulo do foco medido com vlv (para a luz) em vez de -vlv (a partir da luz)
check-cause-spot-direction-untransformed = a direção do foco não transformada para o espaço do olho
check-cause-spot-left-out = o fator do foco não aplicado à contribuição da luz
check-cause-spot-on-whole-colour = o fator do foco aplicado à cor toda (também à emissão e ao ambiente da cena)
check-cause-light-left-out = falta a contribuição de uma luz na soma
check-cause-scene-ambient-left-out = falta o ambiente global da cena na soma
check-cause-scene-ambient-without-material = o ambiente global da cena não multiplicado pelo ambiente do material
check-cause-emission-twice = a emissão do material somada duas vezes
check-cause-colour-not-clamped = a cor não limitada a [0, 1]
check-cause-normal-matrix-not-transposed = a normal pela inversa da 3x3 da modelview sem a transposta
check-cause-row-vectors = vetores multiplicados como linhas (np.matmul(v, mview)): isso é a modelview transposta
check-cause-diffuse-angle-not-cosine = a difusa multiplicada pelo ângulo theta (em radianos) em vez do seu cosseno
check-cause-halfway-with-view-reversed = H = vlv - vov em vez de vlv + vov
check-cause-specular-angle-not-cosine = a potência especular calculada do ângulo beta (em radianos) em vez do seu cosseno
check-cause-attenuation-terms-swapped = os coeficientes linear e quadrático da atenuação trocados (atLin*d*d + atQuad*d)
check-cause-spot-cutoff-not-cosine = o cosseno do foco comparado com o ângulo de corte em graus em vez do cosseno desse ângulo
check-cause-spot-on-diffuse-only = o fator do foco aplicado só à difusa (o OpenGL aplica-o à contribuição toda da luz)
check-cause-only-last-light = só a contribuição da última luz na soma (a variável do ciclo usada depois do ciclo)
check-cause-emission-left-out = falta a emissão do material na soma
check-cause-alpha-from-sum = o alfa da cor tirado de uma quarta componente que é 0 nestas células (I[3], matDif[3]: as cores estão escritas [r g b 0]) em vez do alfa da difusa do material
check-cause-normal-as-point = a normal escrita com w = 1 (como um ponto): a translação desloca-a
check-cause-light-by-mview = a luz transformada pela modelview do vértice, mview, em vez da que estava ativa quando foi colocada (uma luz fixa ao olho movida com a câmara)
check-cause-spot-cutoff-halved = o ângulo de corte tomado como o ângulo total do cone: usada metade
check-cause-spot-not-on-ambient = o fator do foco não aplicado ao termo ambiente da luz
check-cause-attenuation-on-whole-colour = a atenuação a dividir a cor toda (também a emissão e o ambiente da cena)
check-cause-attenuation-on-directional = uma luz direcional (w = 0) atenuada: o OpenGL não a atenua
check-cause-vov-with-w = vov = -vertexPos normalizado com o seu w (-1) no comprimento: o vetor de vista é uma direção, o seu w é 0
check-cause-specular-test-in-degrees = o teste do ângulo especular compara beta em radianos com 90 (graus): nunca corta a especular
check-cause-specular-times-cosine = a especular também multiplicada por N·L (só a difusa o é)
check-cause-shininess-as-product = o brilho como fator (cosBeta*ns) em vez de potência (cosBeta**ns)
check-cause-distance-without-w-divide = a distância calculada com a posição da luz sem dividir pelo seu w (o vlv divide)
check-cause-scene-ambient-wrong-material = o ambiente global da cena multiplicado pela cor difusa ou especular do material em vez da ambiente
check-cause-ambient-outside-share = o termo ambiente da luz fora do fator do foco e da atenuação
check-cause-scene-ambient-times-light = o ambiente global da cena também multiplicado pela cor ambiente da luz
check-cause-specular-of-diffuse-cosine = a potência especular calculada do cosseno difuso (cosTheta**ns) em vez de N·H
check-cause-spot-exponent-as-factor = o expoente do foco como fator (cosSpot*spotCoef) em vez de potência
check-cause-attenuation-inverted = a atenuação invertida (at = 1/(...)) e depois usada a dividir: a luz multiplicada pelo denominador
check-run-stopped = não verificado: a execução parou com um erro antes do fim: { $error }
check-nothing-compared = não verificado: nada do que imprimiu é um passo da ficha; imprima cada valor como a ficha faz, print("vlv = ", vlv)
check-unreadable-steps = não verificado por inteiro: estes passos foram impressos com valores que não são números como o NumPy ou o Python os imprimem ({ $names }); imprima cada valor sozinho
check-missing-steps = não verificado: o caderno não tem valor para { $names }: uma célula não foi executada ou parou com um erro. Execute todas as células (Jupyter: Kernel → Restart & Run All) e depois esta
check-incomplete = incompleto: { $steps }
check-not-printed = a ficha pede { $count ->
        [one] um passo que este trabalho não imprime: { $names }
       *[other] { $count } passos que este trabalho não imprime, o primeiro { $first }: { $names }
    }. Execute todas as células (Jupyter: Restart & Run All, no menu Kernel), imprima cada passo como a ficha faz (print("vlv = ", vlv)) e verifique-o de novo
check-stale-outputs = não verificado por inteiro: as saídas não são de uma só execução, por ordem (uma célula numerada [{ $later }] abaixo de uma numerada [{ $earlier }]: uma célula foi executada de novo, ou fora de ordem). Execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel), guarde e verifique-o de novo
check-after-error = impresso depois do erro, portanto por uma execução anterior (o Run All para num erro), e não verificado: { $names }
# fix57b
py-shade-model-comment = glShadeModel(GL_SMOOTH) desenha o sombreamento para que este programa foi escrito (Gouraud: as cores dos vértices interpoladas; Phong: cada píxel iluminado). Com GL_FLAT, os shaders desenham o que o OpenGL de pipeline fixo desenha: cada face na cor calculada no seu vértice provocante (o último vértice de um triângulo ou de um quadrilátero).
py-two-side-program-comment = Faz com que o gl_Color do fragment shader seja a cor de trás na face de trás de um triângulo, como o GL de pipeline fixo a escolhe; os shaders usam-no com glShadeModel(GL_FLAT).
# phonglab-py: the Python package
python-unknown-value = { $what }{ $value }: os valores possíveis são { $names }
python-wrong-length = { $field }: { $count ->
        [one] foi dado 1 número
       *[other] foram dados { $count } números
    }, esperavam-se { $expected }{ $hint }
python-hint-alpha = ; uma cor é r, g, b, a: acrescente o alfa, como [0.8, 0.2, 0.2, 1]
python-hint-w = ; a posição de uma luz é x, y, z, w: w = 1 para uma luz num ponto, 0 para uma luz muito distante nessa direção, como [0, 0, 90, 1]
python-hint-normal = ; uma normal é uma direção: x, y, z, ou x, y, z, 0 como na ficha (o seu w é 0)
python-hint-vertex = ; um vértice é x, y, z (o w fica 1) ou x, y, z, w
python-either-3-or-4 = 3 ou 4
python-no-such-light = não há luz { $light }: a cena tem { $count ->
        [0] nenhuma luz
        [one] 1 luz, numerada 0
       *[other] { $count } luzes, numeradas a partir de 0
    }
python-not-real = { $what } = { $value }: não é um número. Dê números reais: um int ou um float, ou uma lista ou matriz NumPy deles (um texto, True ou False, None e números complexos não são lidos como números; em Python escreva 25.6, não "25,6")
python-not-integer = { $what } = { $value }: não é um número inteiro; dê um int, por exemplo 5
python-not-a-scene = { $what }: { $value } não é uma phonglab.Scene; crie uma primeiro: phonglab.Scene.load("cena.toml"), phonglab.Scene.worksheet(5) ou phonglab.Scene.preset("phong-demo")
python-not-a-name = { $what } = { $value }: não é um texto; dê uma str, como scene.name = "câmara da mview3"
python-edit-fields = { $what } não se substitui por inteiro: edite os seus campos um a um, como { $example }
python-load-notebook = { $path } é um caderno ou um script, não um ficheiro de cena: leia a cena que ele define com phonglab.Scene.from_notebook(caminho)
python-no-field-guess = { $what } não tem { $value }: quis dizer { $guess }? Os seus nomes: { $names }
python-no-field = { $what } não tem { $value }; os seus nomes: { $names }
python-lights-fixed = scene.lights não tem { $value }: as luzes são as da cena, editadas aqui campo a campo (scene.lights[0].position = ...); uma luz acrescenta-se ou retira-se num ficheiro de cena, que o Scene.load depois lê
python-no-memory = memória insuficiente: não foi possível obter { $bytes } bytes; ilumine os vértices em blocos mais pequenos
python-check-reassigned = Nota: { $name } volta a ser atribuído numa célula corrida depois da que o imprime, por isso a autoverificação lê o valor que { $name } tem agora, não o impresso (o phonglab check lê o impresso). Use lá outro nome, ou volte a correr as células por ordem.
python-overflow = { $step } dá { $value } em { $precision }: os números da cena passam do que o { $precision } guarda (float32: ±3,4e38), por isso a iluminação transborda; nada é devolvido (precision="f64" guarda mais)
python-render-no-memory = memória insuficiente para desenhar uma imagem de { $size } x { $size }: precisa de cerca de { $bytes }, pede-se primeiro o dobro, e não foi possível obtê-lo; escolha um tamanho mais pequeno
python-not-finite-row = { $name }: a linha { $row } é { $value }: todos os números têm de ser finitos e estar dentro do alcance do float32 (±3,4e38)
python-wrong-shape = { $name }: uma matriz de forma { $shape }, quando se espera (N, 3), com o mesmo N para as posições e as normais
nb-self-check = Autoverificação: com o pacote Python phonglab instalado (ainda não está no PyPI: instale o ficheiro wheel, `pip install phonglab-*.whl`, que o `scripts/wheel` do phonglab constrói ou que o professor distribui), retire o comentário da célula abaixo e execute-a depois das outras. Compara cada valor que este caderno calculou com a solução, passo a passo, e indica o primeiro passo errado e a causa provável. Nada mais neste caderno depende dela.
check-rules = regras assumidas: { $rules }
check-inputs-differ = os dados que escreveu diferem dos do enunciado: { $names }
check-other-scene = { $count } dos dados que escreveu diferem dos do enunciado: é esta a cena certa (--scene)? Não se nomeia nenhuma causa para um trabalho escrito para outra cena
check-step = { $step }: o seu { $student }, o da solução { $key }: { $verdict }
check-first-wrong = primeiro passo errado: { $step } (o seu { $student }, o da solução { $key })
check-all-right = tudo certo: todos os passos impressos são os da solução
check-cause = causa provável: { $words } [{ $id }]. Evidência: em { $step }, imprimiu { $student }, e a solução com este erro dá { $value }
check-cause-formula = a fórmula com este erro (um modelo dele, não o seu código): { $formula }
check-no-cause = nenhum erro do catálogo reproduz tudo o que imprimiu; veja o primeiro passo errado
check-given-not-finite = não verificado: um dado não é um número finito ({ $givens })
check-printed-twice = impresso mais de uma vez, com valores diferentes (cada impressão é verificada): { $names }
check-input-rules = as regras
check-given-not-followed = não verificado: um dado é alterado no próprio lugar, o que a verificação não segue ({ $givens }): atribua-o inteiro numa só linha
# py58b: the notebook's self-check, the worked calculation's table
python-check-no-cells = phonglab.check(globals()) verifica um caderno Jupyter: lê as células já executadas do In do caderno, e este Python não o tem. Para um programa, guarde o que ele imprime e verifique isso: python3 programa.py > impresso.txt, depois phonglab check --printed impresso.txt
python-check-run-first = ainda não há nada para verificar: nenhuma célula da ficha foi executada neste kernel (também depois de o reiniciar). Execute primeiro as outras células (Run All) e depois esta
python-check-not-globals = o phonglab.check lê as variáveis do caderno: passe globals(), com os parênteses: phonglab.check(globals())
explain-column-step = passo
explain-column-formula = fórmula
explain-column-value = valor
explain-column-notes = notas
share-base-refused = a página que uma ligação abre tem de ser um endereço http:// ou https://, sem espaços, aspas nem caracteres de controlo: { $base }

## Files read and written (formats::files): shared by the command line, the window and the Python package

io-folder-missing = a pasta { $folder } não existe: crie-a primeiro, ou indique um ficheiro numa pasta que exista
io-not-found = não existe
io-permission-denied = sem permissão
io-storage-full = o disco está cheio
io-open-elsewhere = outro programa tem-no aberto (feche-o lá e tente de novo)
io-handle-lost = o sistema perdeu o rasto de um ficheiro ou pasta que o phonglab tinha aberto: uma pasta em que trabalhava foi renomeada ou substituída por uma ligação enquanto escrevia (no Wine, por um programa fora do Wine)
io-link-in-the-way = está uma ligação no caminho (posta lá, ou mudada enquanto o phonglab escrevia): aqui o phonglab nunca segue uma
io-is-a-directory = é uma pasta
io-not-a-directory = uma parte do caminho não é uma pasta
io-read-only = o sistema de ficheiros é só de leitura
io-already-exists = já existe
io-invalid-name = não é um nome de ficheiro
write-error = não foi possível escrever { $path }: { $what }: { $reason }; { $kept }
write-step-write = escrever
write-step-close = fechar
write-step-sync = sincronizar com o disco
write-step-create = criar
write-step-rename = mudar o nome
write-step-name = nome
write-step-create-folder = criar a pasta
set-folder-is-a-file = é um ficheiro, não uma pasta: o phonglab escreve um conjunto de ficheiros numa pasta; indique uma pasta, ou o nome de uma pasta nova
folder-link-dangling = é uma ligação cujo destino não existe, e o phonglab não cria pastas através de uma ligação
write-step-create-file-in = criar um ficheiro em
write-kept-file = o ficheiro que lá estava (se havia) não mudou
write-kept-nothing = nada foi escrito
write-not-a-regular-file = não é um ficheiro normal (uma ligação, uma pasta, um dispositivo ou um pipe): o phonglab só escreve num ficheiro normal ou num novo
read-cannot = não foi possível ler { $path }: { $reason }
read-not-a-file = { $path } não é um ficheiro normal
read-device-name = { $path } é um nome que o Windows reserva para um dispositivo (CON, PRN, AUX, NUL, COM1…, LPT1…), não um ficheiro: o phonglab não lê dispositivos; indique o nome do próprio ficheiro
read-too-large = { $path } tem { $size }; o phonglab lê { $what } de no máximo { $cap }
read-not-utf8 = { $path } não é texto UTF-8 (byte { $byte })
read-link-refused = { $path } é uma ligação simbólica: não foi lido (o trabalho de um aluno só é lido de um ficheiro, nunca através de uma ligação)
file-kind-scenes = ficheiros de cena
file-kind-code = cadernos e programas
err-output-is-input = { $output } é { $what } { $input }, que este comando lê (o mesmo ficheiro): escrevê-lo destruiria o que é lido; escolha outra saída
err-output-is-other-output = { $output } é a outra saída { $other } (o mesmo ficheiro): uma seria escrita por cima da outra; escolha dois ficheiros diferentes
err-name-windows-device = { $name } é um nome que o Windows reserva para um dispositivo; escolha outro
err-name-windows-char = { $name } contém “{ $char }”, que o Windows não permite num nome de ficheiro (um “:” escreve um fluxo oculto de outro ficheiro); escolha um nome sem ele
err-name-windows-quote = { $name } contém “"”, que o Windows não permite num nome de ficheiro. No cmd, uma barra invertida mesmo antes das aspas finais guarda as aspas e junta ao nome o que vem a seguir: escreva a pasta sem a última barra ("C:\Exercícios de CG", e não "C:\Exercícios de CG\")
err-name-windows-end = o Windows retira o ponto ou o espaço no fim de um nome ({ $name } seria { $kept }, outro ficheiro); escolha um nome sem ele
input-kind-input = a entrada
input-kind-scene = a cena
input-kind-mesh = a malha
input-kind-code = o caderno ou programa
input-kind-cases = o ficheiro de casos
# fix57c
check-verdict-too-few-digits = dígitos a menos para decidir (impresso com { $decimals ->
        [one] 1 casa decimal
       *[other] { $decimals } casas decimais
    }, que não distinguem a solução do valor de um erro ou de 0: imprima mais, por exemplo np.set_printoptions(precision=8))
check-too-few-digits = não verificado por inteiro: dígitos a menos para distinguir a solução do valor de um erro ou de 0 ({ $names }; { $decimals ->
        [one] 1 casa decimal
       *[other] { $decimals } casas decimais
    }). Imprima mais dígitos (np.set_printoptions(precision=8) no início, ou o que o NumPy usa por omissão), execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel) e verifique-o de novo
check-stale-count = não verificado por inteiro: o número de execução de uma célula não é o de uma execução ([{ $count }]: o Jupyter numera as células que executa 1, 2, 3, por ordem), portanto nada diz que as saídas são de uma só execução, por ordem. Execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel), guarde e verifique-o de novo
check-stale-not-run = não verificado por inteiro: uma célula de código entre as numeradas [{ $above }] e [{ $below }] não tem número de execução (não foi executada nessa execução, ou as suas saídas foram apagadas), portanto as saídas abaixo dela não são do seu código executado por ordem. Execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel), guarde e verifique-o de novo
