# As mensagens do phonglab em português do Brasil.

## app

present = Apresentar (F5)
space-object = Objeto
space-world = Mundo
space-eye = Olho
wrong-cause-normals-by-m = Normais transformadas por M em vez de sua inversa transposta
wrong-why-normals-by-m = Com uma escala diferente em cada eixo, M move a superfície de um jeito e as normais de outro: M n deixa de ser perpendicular à superfície, e (M^-1)^T n continua sendo.
wrong-cause-normal-not-normalised = A normal não normalizada (GL_NORMALIZE desligado com uma modelview que escala)
wrong-why-normal-not-normalised = Uma modelview que escala por { $scale } deixa a normal transformada com comprimento 2, e nada a traz de volta a 1: n · L dobra, e com ele o termo difuso; perto do brilho, n · H passa de 1, e a potência s_rm faz o termo especular explodir em uma mancha branca.
wrong-cause-reflection-for-halfway = O vetor refletido (R · V) usado onde cabe o vetor médio (n · H)
wrong-why-reflection-for-halfway = O ângulo entre R e V é cerca do dobro do ângulo entre n e H, por isso R · V cai mais rápido: com o mesmo expoente o brilho é menor.
wrong-cause-gouraud-misses-highlight = Sombreamento de Gouraud: iluminado só nos vértices, e um brilho entre eles se perde
wrong-why-gouraud-misses-highlight = O brilho cai entre os vértices da esfera grosseira: nenhum deles o vê, e interpolar suas cores não pode criá-lo.
wrong-cause-specular-facing-away = Luz especular em faces voltadas para o lado oposto à luz (sem f_i)
wrong-why-specular-facing-away = O OpenGL multiplica o termo especular por f_i, que só vale 1 onde n · L > 0. Sem ele, n · H ainda pode ser positivo no lado escuro: brilha onde a luz não chega.
wrong-cause-attenuation-object-space = Atenuação calculada com a distância no espaço do objeto
wrong-why-attenuation-object-space = O modelo escala por { $scale }, por isso as distâncias no espaço do objeto são 4 vezes as do espaço do olho: at = k0 + k1 d + k2 d² cresce, cada termo é dividido por mais, e a luz se apaga cedo demais. O OpenGL mede d no espaço do olho.
wrong-cause-light-before-view = A posição da luz dada antes da transformação de visão
wrong-why-light-before-view = O glLightfv(GL_POSITION) multiplica a posição pela modelview corrente nesse momento. Dada antes do gluLookAt, é tomada em coordenadas do olho: a luz anda com a câmera em vez de ficar no mundo.
wrong-probe-line = bytes { $rgba }, n · L = { $ndotl }, { $cosine } = { $ndoth }, 1/at = { $att }, difusa { $diffuse }, especular { $specular }
wrong-key-cause = Causa: { $cause }.
wrong-key-formulas = Certo: { $right }. O erro: { $wrong }.
wrong-formula-gouraud-right = iluminação em cada fragmento (Phong)
wrong-formula-gouraud-wrong = iluminação em cada vértice e cores interpoladas (Gouraud)
wrong-formula-facing-away-right = f_i = 1 só onde n · L > 0
wrong-formula-facing-away-wrong = f_i = 1 em todo lugar
wrong-formula-attenuation-right = d = |P_pli - P| no espaço do olho
wrong-formula-attenuation-wrong = d medida no espaço do objeto
wrong-formula-light-right = gluLookAt(...) e depois glLightfv(GL_POSITION, p)
wrong-formula-light-wrong = glLightfv(GL_POSITION, p) e depois gluLookAt(...)
wrong-key-pixel = A sonda no pixel ({ $x }, { $y }), onde as duas imagens mais diferem ({ $count } pixels diferem):
wrong-key-right = desenhada corretamente: { $line }
wrong-key-wrong = com o erro: { $line }
wrong-key-term = O termo que mais muda neste pixel: { $term } ({ $name }), com a luminância passando de { $right } na imagem certa para { $wrong } na imagem com o erro.
wrong-key-normals = A normal do fragmento gira { $degrees }°.
share-too-long = o link tem { $length } caracteres; o phonglab lê no máximo { $most }
share-version = o link é da versão “{ $found }”; este phonglab lê a v{ $version }
share-damaged = o link está danificado: foi cortado ou alterado no caminho. Copie de novo o link inteiro, do início ao último caractere
share-choice = o link pede algo que este phonglab não conhece: “{ $line }”
scene-link-refused = { $link }: { $why }
scene-link-empty = o link não contém nenhuma cena (o link de uma cena compartilhada termina em #v1. e nos dados da cena): copie o link inteiro
share-too-big = descompactada, passa de { $most } bytes, mais do que o phonglab lê (mais do que qualquer cena que o phonglab escreve)
share-make-too-long = o link teria { $length } caracteres, e o phonglab abre links de no máximo { $most }: encurte o nome da cena
share-mesh-folders = o link nomeia a malha “{ $path }” com as pastas dela; um link leva só o nome do arquivo da malha, e o phonglab nunca lê um caminho que um link nomeie: fica só o nome { $name } (abra esse arquivo para vê-la), e a esfera é mostrada até lá
mesh-missing-kept = A malha { $path } está faltando ou não pode ser lida ({ $error }); a cena é mantida e mostrada na esfera. Abra a malha de novo para vê-la.
shader = Programa de sombreamento (shader)

## names

doc-worksheet = a lista, mview{ $k }
doc-worksheet-preset = Lista, mview{ $k }

## presets

doc-phong-demo = a demo de Phong
doc-spotlight = um foco
doc-three-lights = três luzes coloridas e uma luz presa ao observador
doc-of-set-color = ofSetColor do openFrameworks com iluminação
doc-gouraud-misses-the-highlight = por que o Gouraud perde o brilho
doc-redbook-teapot = bules do Red Book: { $material }

## controls

specular-blinn-phong-normalised = Blinn-Phong normalizado (n.H)·(ns+8)/8π
ruleset-worksheet = Lista de exercícios
ruleset-demo = Demo de Phong
pow-exact = pow exata
lights-count =
    { $count ->
    [0] { $count } luzes
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
quantity-light-modelview = Modelview quando a luz foi posicionada
scene-ambient = Ambiente da cena
local-viewer = Observador local
two-sided = Iluminação das duas faces
vertex = Vértice
normal = Normal
camera = Câmera
camera-kind-worksheet = Modelview da lista
camera-kind-of = Câmera do openFrameworks
camera-kind-matrix = Matriz 4x4 digitada

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
note-color-material = GL_COLOR_MATERIAL ({ $mode }, { $face }): { $name } é a cor atual (glColor) { $color }, e não o { $set } definido por glMaterial
formula-normal-gl = vertexNormal = (M^-1)^T · vertexNormal   (o N do OpenGL)
formula-normal-gl-normalize = vertexNormal = normalize((M^-1)^T · vertexNormal)   (o N do OpenGL, GL_NORMALIZE)
formula-normal-gl-rescale = vertexNormal = f · (M^-1)^T · vertexNormal, f = 1/|linha 3 de M^-1|   (o N do OpenGL, GL_RESCALE_NORMAL)
formula-normal-ws = vertexNormal = mview · vertexNormal   (a lista: a própria M; OpenGL: (M^-1)^T)
formula-normal-ws-normalize = vertexNormal = normalize(mview · vertexNormal)   (a lista: a própria M; OpenGL: (M^-1)^T)
formula-normal-ws-rescale = vertexNormal = f · mview · vertexNormal, f = 1/|linha 3 de M^-1|   (a M da lista)
formula-position = vertexPos = mview · vertexPos, dividido por w   (OpenGL: P = M v)
formula-light-position = lightPos = mview · lightPos   (OpenGL: P_l, a modelview de quando a luz foi colocada vezes GL_POSITION)
formula-l-positional = vlv = normalize(lightPos − vertexPos)   (OpenGL: L = normalize(P_l − P))
formula-l-directional = vlv = normalize(lightPos)   (direcional, w = 0; OpenGL: L = normalize(P_l.xyz))
formula-v-local = vov = normalize(obs − vertexPos), obs = [0 0 0 1]   (observador local; OpenGL: V = −P/|P|)
formula-v-worksheet = vov = normalize(obs − vertexPos), obs = vertexPos · [1 1 0 1]   (o observador no infinito da lista: (0, 0, −sinal z))
formula-v-infinite = vov = [0 0 1 0]   (observador no infinito; OpenGL: V = (0, 0, 1))
formula-r-demo = R = 2 max(vertexNormal · vlv, 0) vertexNormal − vlv   (o da demo)
gate-lit-side = f = 1 se cosTheta > 0, senão 0
gate-positive = f = 1 se { $cos } > 0, senão 0
gate-none = sem condição: f = 1 sempre
formula-specular = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns   ({ $gate }; f = { $f }; OpenGL: s_cl · s_cm · max(n · h, 0)^s_rm)
formula-specular-normalised = Ispec = Lspec · matSpec · max({ $cos }, 0)^ns · (ns + 8)/(8π)   ({ $gate }; f = { $f }; Blinn-Phong que conserva a energia: quanto mais estreito o brilho, mais intenso, e a luz que ele reflete se mantém; o OpenGL não tem esse fator)
formula-at = at = atC + atLin · d + atQuad · d²   (OpenGL: as componentes são divididas por k0 + k1 d + k2 d²)
formula-at-directional = at = 1   (direcional)
formula-spot = spot = max(−L · s, 0)^e se −L · s >= cos(cutoff) = { $cutoff }, senão 0;  −L · s = { $angle }
formula-spot-none = spot = 1   (abertura de 180°: não é um foco)
formula-share-separate = Ilight = spot · (Iamb + Idif) / at   (a especular vai para a cor secundária)
formula-scene-ambient = a_cm a_cs   (ambiente do modelo de iluminação)
formula-i-opengl = I = e_cm + a_cm a_cs + soma das partes das luzes
formula-i-worksheet = I = (Iamb + Idif + Ispec) / at, somado sobre as luzes   (o I da lista)
formula-secondary = soma de spot · Ispec / at   (especular separada)
formula-clamped = rgba limitado a [0, 1]; alfa = alfa da difusa
note-demo-space = a demo de Phong ilumina no espaço do objeto com o olho em (-4, 0, -8); aqui o espaço do olho é o espaço do objeto deslocado de (4, 0, 8), para que esse olho seja a origem: cada vetor e componente é o da demo
note-vov-behind = o texto da lista diz que vov é sempre [0 0 1 0]; o seu código dá aqui [0 0 -1 0], porque o vértice está atrás do olho (z > 0)
note-no-distance = luz direcional: sem distância
mview-note-gap = por isso M n, a normal da lista, aponta a { $angle } da (M^-1)^T n do OpenGL, e N e cada componente a seguir diferem dos do OpenGL
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
object-mesh = Sua malha
framing-orbit = Câmera em órbita
framing-clip = Espaço de recorte (o da demo)
fix-light-world = luz presa ao mundo
fix-true-normals = as normais verdadeiras da superfície
fix-highlight-colour = brilho da cor da luz
why-light-world = A demo ilumina posições e normais não transformadas, por isso a luz gira com o objeto; a correção do próprio documento as transforma pela mvMatrix (para uma rotação, a inversa transposta é ela própria), e a luz fica parada enquanto o objeto gira.
why-true-normals = normalize(posição) só é a normal de uma esfera centrada na origem; as superfícies do bule e do cilindro apontam para outros lados, e suas normais verdadeiras as iluminam como são.
why-highlight-colour = A demo multiplica a componente especular pelo vermelho do objeto; o OpenGL multiplica a cor especular da luz pela cor especular do material (aqui branca), por isso o brilho mostra a cor da luz.

## student-code

export-target-notebook = Notebook Jupyter (o da lista)
export-target-pyopengl = Programa em Python (PyOpenGL + GLUT)
export-target-openframeworks = App openFrameworks (ofApp.h, ofApp.cpp, main.cpp)
export-target-glsl = Shaders GLSL
notebook-refused = o notebook não é escrito para esta cena: o explain toma aqui um limite ({ $reason }), e o NumPy do notebook imprimiria nan ou pararia; exporte-a como programa PyOpenGL, ou mude a cena
nb-title =
    # Cálculo da cor dos vértices com iluminação em OpenGL atual

    Cena: **{ $scene }**, escrita pelo phonglab (regras: { $rules }).

    obs: modifique os valores das variáveis de acordo com a configuração que está sendo utilizada no app do OpenFrameworks; cada célula imprime o que o `phonglab explain` imprime, passo a passo.
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
nb-settings = O que esta cena usa além da lista (o phonglab escreveu as células seguintes para estas opções; para as mudar, mude a cena no phonglab e exporte de novo):
nb-modelview =
    Inicialização da matriz modelview

    o lookat vai transformar a matriz modelview, para fazer os cálculos precisaremos transformar os vetores e posições que utilizamos com a matriz modelview.
nb-light-mview-comment = # a posição de cada luz é transformada pela modelview que estava ativa quando se chamou glLight(GL_POSITION)
nb-color-material-comment = # GL_COLOR_MATERIAL ({ $mode }, { $face }): as cores do material que acompanha são a cor atual, glColor = { $color }, e não as definidas por glMaterial
nb-vectors =
    Calcular os vetores necessários e normalizá-los:

    - normal do vértice
    - vetor luzPos - vérticePos (vlv)
    - vetor obsPos - vérticePos (vov)

    No caso da luz ser direcional, o vetor (luzPos-vérticePos) é desnecessário, usamos o próprio luzPos

    O vetor (obsPos - vérticePos) é calculado de forma diferente para `glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, true/false)`: quando **true**, obs = [0 0 0 1]; quando **false**, obs = (vertexPos) * [1 1 0 1], o vértice com z igual a 0, e portanto vov = obs - vertexPos = [0 0 -z 0] antes de ser normalizado: só sobra a componente z.

    A lista diz de **false**: "vov vai sempre resultar em [0 0 1 0]". Isso só vale para um vértice na frente do olho (z < 0 no espaço do olho): para um vértice atrás do olho (z > 0) essa fórmula dá [0 0 -1 0], e com z = 0 o vov não tem direção para normalizar (0/0). (O observador no infinito do OpenGL é sempre V = (0, 0, 1).)

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
    Blinn-Phong normalizado (que conserva a energia), como nos motores gráficos atuais: a componente é multiplicada por (ns + 8)/(8π), de modo que um brilho mais estreito (ns maior) fica mais intenso e a luz que ele reflete continua aproximadamente a mesma. A iluminação de pipeline fixo do OpenGL não tem esse fator.
nb-attenuation =
    Calculo da atenuação:

    - at = at<sub>constante</sub> + d × at<sub>linear</sub> + d² × at<sub>quadrática</sub>

    só vale para luz pontual ou foco!
nb-spot = O foco: dentro do cone (o ângulo entre -vlv e a direção do foco no máximo spotCutoff), spot = cos<sup>spotCoef</sup> desse ângulo; fora, 0; 1 para uma luz que não é foco (spotCutoff 180).
nb-final =
    Calculo final:

    - I<sub>final</sub> = (I<sub>amb</sub> + I<sub>dif</sub> + I<sub>spec</sub>)/at
nb-glcolor-comment = # a cor desenhada: limitada a [0, 1]; o alfa é o da cor difusa tal como o OpenGL a ilumina (1, ou matAlpha; o da cor atual quando GL_COLOR_MATERIAL segue a difusa), não matDif[3]: as cores acima estão escritas [r g b 0]
nb-back = A face de trás (iluminação das duas faces): os mesmos termos com a normal invertida (-vertexNormal) e o material de trás; os nomes terminam em Back.
nb-no-spot-comment = # não é um foco (spotCutoff 180)
import-unreadable = { $place }: não consigo ler `{ $line }`: { $reason }; ignorada
import-changed-in-place = altera um dado no próprio lugar (uma parte dele, ou com +=, *=, ...), o que o phonglab não segue: atribua o valor inteiro em uma só linha
import-no-givens = isto não é um notebook nem um programa no estilo da lista: não atribui nenhuma de vertexPos, vertexNormal, lightPos, matDif, mview
import-not-notebook = não é um notebook Jupyter: { $reason }
import-no-cells = não tem células
import-place-cell = célula { $cell }, linha { $line }
import-place-line = linha { $line }
import-reason-extra = `{ $token }` inesperado
import-reason-string = uma cadeia de caracteres não está fechada
import-reason-char = o caractere `{ $char }` não é compreendido
import-reason-expected = esperava `{ $token }`, encontrei `{ $found }`
import-reason-end = a expressão acaba cedo demais
import-reason-number = `{ $token }` não é um número
import-reason-name = `{ $name }` não é conhecido aqui (só se leem números, arrays e nomes atribuídos antes)
import-reason-arithmetic = `{ $op }` entre valores de formas diferentes
import-missing = { $name } não é atribuído: usa-se o valor da lista, { $value }
import-malformed = { $place }: { $name } devia ser { $want }; usa-se o valor da lista
import-want-vector = 4 números, [x, y, z, w]
import-want-number = um número
import-want-matrix = 4 linhas de 4 números
import-not-finite = { $place }: { $name } é { $value }, não um número finito; usa-se o valor da lista
import-too-large = { $place }: `{ $line }` { $reason }: o arquivo não é lido (os dados de uma lista são alguns vetores pequenos)
import-limit-depth = aninha mais de { $depth } níveis
import-limit-elements = contém mais de { $count } números, strings e listas
import-limit-bytes = contém mais de { $count } bytes de strings
import-limit-tokens = tem mais de { $count } tokens (números, nomes, operadores e parênteses)
import-limit-total = leva os nomes atribuídos até aqui além do que o phonglab lê: { $limit }
bytes-described = { $count ->
        [0] { $bytes } bytes
        [one] { $bytes } byte
       *[other] { $bytes } bytes
    } ({ $scaled })
bytes-counted = { $count ->
        [0] { $bytes } bytes
        [one] { $bytes } byte
       *[other] { $bytes } bytes
    }
obj-index-not-number = linha { $line }: o índice de { $what } { $index } não é um número
obj-index-out-of-range = linha { $line }: o índice de { $what } { $index } está fora do intervalo (há { $count })
obj-what-vertex = vértice
obj-what-texture = textura
obj-what-normal = normal
obj-cannot-read-line = linha { $line }: não é possível ler: { $error }
obj-line-too-long = a linha { $line } tem mais de { $bytes } bytes: não é um arquivo OBJ
obj-too-many-triangles = linha { $line }: mais de { $max } triângulos, o máximo que o phonglab sombreia
obj-not-a-number = linha { $line }: { $word } não é um número
obj-vertex-needs = linha { $line }: um vértice precisa de 3 números finitos
obj-normal-needs = linha { $line }: uma normal precisa de 3 números finitos
obj-face-needs = linha { $line }: uma face precisa de pelo menos 3 vértices
obj-no-faces = não há faces
obj-note-fanned = as faces de mais de 3 vértices (a primeira na linha { $line }) foram divididas em leque de triângulos
obj-note-normals = faces sem normais (a primeira na linha { $line }): as normais dos seus vértices foram calculadas como a média das normais das faces, ponderada pela área
obj-note-fitted = centralizada e escalada por { $scale } para caber na vista (raio 0,5)
obj-beyond-single = coordenadas fora do alcance da precisão simples: abra o arquivo para ajustá-las à vista
obj-cannot-read = não é possível ler { $path }: { $error }
obj-not-a-file = { $path } não é um arquivo comum
obj-too-large = { $path } tem { $size }; o phonglab lê arquivos OBJ de no máximo { $max } (cerca de { $millions } milhões de triângulos)
obj-over-budget = ler { $count ->
        [0] { $triangles } triângulos
        [one] { $triangles } triângulo
       *[other] { $triangles } triângulos
    } ocupa { $bytes }, mais do que o orçamento de memória de { $budget } (--memory-budget o aumenta)
export-flat-unsupported = o programa PyOpenGL desenha com os shaders gerados para a cena, que são Gouraud ou Phong: escolha um deles para a vista sombreada, não Flat
export-template-broken = o modelo de programa { $template } está mal preenchido ({ $problem }): é uma falha do phonglab; por favor, informe-a
py-title = { $scene }: a vista sombreada como o phonglab a desenha (sombreamento { $shading }), escrita pelo phonglab.
py-usage = Execute este arquivo com python3 (uma janela; precisa de PyOpenGL, GLUT e NumPy). Com --png ARQUIVO desenha um quadro de 512x512 (--size N: NxN), salva-o em ARQUIVO e termina. O estado da iluminação é definido à maneira do pipeline fixo (glLightfv, glMaterialfv, glLightModel*), e os shaders abaixo calculam toda a iluminação do OpenGL 2.1 a partir desse estado, lido do GL a cada quadro: mude qualquer uma dessas chamadas e a imagem muda como mudaria no OpenGL de pipeline fixo, exceto onde um comentário junto da chamada disser o contrário.
py-rules-comment = O conjunto de regras para o qual os shaders foram escritos: "worksheet", "opengl" ou "phong-demo". Só a matriz das normais em set_uniforms() lê o RULES; o resto do conjunto de regras (inclusive a ambiente da cena e a emissão) são as linhas #define dos shaders.
py-shaders-comment = Os shaders: toda a iluminação do OpenGL 2.1 (por vértice no Gouraud, por fragmento no Phong), lendo o próprio estado do GL: gl_LightSource[], gl_FrontMaterial, gl_BackMaterial, gl_LightModel e os uniforms u_ que set_uniforms() lê com glGet*. Só as linhas #define são desta cena (os desvios do seu conjunto de regras em relação ao OpenGL); o `phonglab shader` imprime em vez disso os shaders especializados da cena.
py-projection-orbit = a câmera em órbita do phonglab: gluPerspective(40, 1, 0.1, 100)
py-projection-clip = nenhuma projeção: a imagem é o próprio espaço de recorte (o da demo de Phong)
py-modelview-comment = a modelview com que o objeto é desenhado: a câmera, depois a rotação do objeto (linhas)
py-lighting-modelview-comment = a modelview que a iluminação usa, onde não é a do desenho (a demo ilumina no espaço do objeto)
py-color-material-comment = GL_COLOR_MATERIAL: as cores do material que acompanha são a cor atual (glColor); u_color é essa cor
py-normalised-comment = Blinn-Phong normalizado: a componente especular vezes (ns + 8)/(8π); o GL de pipeline fixo não tem esse fator, então só o shader abaixo o calcula (a iluminação do próprio GL a partir desse estado não faria isso)
py-light-eye = colocada sob a identidade: a luz move-se com o olho
py-light-object = colocada sob a modelview inteira: a luz gira com o objeto
py-light-world = colocada sob a matriz de vista: a luz fica parada no mundo
py-state-doc = O estado da iluminação da cena, definido à maneira do pipeline fixo. O GL_POSITION e o GL_SPOT_DIRECTION de cada luz são transformados pela modelview ativa quando são definidos, por isso o GL guarda-os no espaço do olho.
py-reader-doc = Passa aos shaders o que o GLSL não tem em nenhuma variável, lido do estado do GL a cada quadro: a modelview da iluminação e a matriz das normais, as luzes ligadas, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_COLOR_CONTROL, GL_NORMALIZE ou GL_RESCALE_NORMAL, GL_COLOR_MATERIAL e GL_SHADE_MODEL.
py-editable-comment = Você pode mudar qualquer chamada abaixo (um valor de glLight*, glMaterial* ou glLightModel*, o glEnable ou glDisable de uma luz, GL_NORMALIZE, GL_COLOR_MATERIAL): os shaders leem este estado a cada quadro e desenham o que o OpenGL de pipeline fixo desenharia a partir dele, exceto onde um comentário abaixo disser o contrário. O RULES e as linhas #define dos shaders não são estado do GL: ficam como estão escritos.
py-lighting-comment = Os shaders iluminam o objeto com ou sem GL_LIGHTING ativo: com glDisable(GL_LIGHTING), o OpenGL de pipeline fixo desenharia a cor atual (glColor) sem iluminação; estes shaders não.
py-scene-ambient-off = SCENE_AMBIENT é 0 com estas regras: os shaders não somam nem esta ambiente da cena nem a GL_EMISSION do material, então mudar qualquer uma delas aqui não muda nada (o OpenGL de pipeline fixo somaria as duas).
py-object-doc = O objeto, tal como o phonglab o constrói.
py-arrays-comment = os triângulos do phonglab (posições, normais e três índices de vértices por triângulo)
py-teapot-winding = o bule do freeglut tem os triângulos no sentido horário: com iluminação das duas faces, o exterior seria iluminado como face de trás
of-header-comment = { $scene }: a sua iluminação num app openFrameworks 0.12, escrito pelo phonglab. Supõe o renderizador padrão do oF: o ofSetupOpenGL abre uma janela GL 2.1, onde o ofGLRenderer ilumina com o OpenGL de pipeline fixo (não o renderizador programável do GL 3+).
of-main-comment = O renderizador por padrão: GL 2.1, iluminação de pipeline fixo (ver ofApp.h).
of-source-comment = As luzes, o material e a câmera da cena como o phonglab os tem; o oF coloca as luzes em coordenadas do mundo, só sob a vista da câmera.
of-camera-comment = a vista do phonglab: gluPerspective(40, 1, 0.1, 100) e a sua câmera em órbita
of-light-comment = a luz { $index } da cena
of-directional-comment = o GL_POSITION de uma luz direcional é a sua direção de olhar, w = 0
of-spot-comment = a direção do foco é a direção de olhar da luz
of-material-comment = o material, ativo enquanto o objeto é desenhado (ofSetColor com iluminação ligaria antes o glColorMaterial)
of-back-material-comment = o oF tem um material para as duas faces: o da face de trás, em GL direto
of-color-material-comment = GL_COLOR_MATERIAL: as cores do material que acompanha seguem a cor atual, definida por ofSetColor
of-normalised-comment = Blinn-Phong normalizado: a componente especular vezes (ns + 8)/(8π); o GL de pipeline fixo não tem esse fator, então o aplicativo desenha com o shader gerado pelo phonglab (as luzes e o material do oF só definem o estado do GL)
of-shader-comment = os shaders gerais (toda a iluminação do OpenGL, lida do estado do GL), para o que o GL de pipeline fixo não calcula: só as suas linhas #define são o conjunto de regras desta cena; as luzes e o material são as chamadas de oF e de GL deste aplicativo
of-shader-state-comment = o que o GLSL não tem em nenhuma variável, lido do estado do GL a cada quadro (os shaders leem eles mesmos as luzes, o material e a ambiente da cena): mude qualquer chamada de luz, de material ou do modelo de iluminação e a imagem acompanha
of-no-scene-ambient = as regras desta cena não têm ambiente da cena: 0 aqui, para o GL calcular o mesmo I (o oF usa 0,2 por padrão)
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
of-no-teapot-comment = o oF não tem bule e aqui não lê arquivos de malhas: uma esfera faz as vezes (carregue o seu modelo com ofMesh::load ou ofxAssimpModelLoader)
py-normal-matrix-comment = OpenGL: a inversa transposta da 3x3 da modelview; a lista: a própria 3x3.

## compare

shader-step = passo { $n }
shader-note-directional-l = direcional: um só L para todos os vértices
shader-note-one-h = um só H: luz direcional, observador no infinito
shader-note-spot-cosine = cosseno do spot
shader-note-cone-test = o teste do cone
shader-note-alpha = alfa: o alfa difuso
shader-note-zero-normal = uma normal nula não tem direção: nem difusa, nem especular
shader-note-emission-ambient = emissão + ambiente da cena
shader-note-secondary = a cor secundária
shader-note-projective = a modelview é projetiva: dividir por w
shader-note-translation = a modelview é uma translação: sua última coluna
shader-note-affine = modelview afim: w = 1, sem divisão
shader-note-normal-by-m = a lista: a própria M
shader-header = phonglab: { $what }, sombreamento de { $shading }, gerado a partir do plano especializado.
    Só as etapas que o gabarito desta cena pede; os comentários dão os passos do cálculo.
shader-what-vertex-lighting = a iluminação por vértice
shader-what-program = O programa
shader-what-program-fragment = O programa por fragmento
shader-what-fragment-vertex-stage = a etapa de vértices da iluminação por fragmento
shader-what-fragment-lighting = a iluminação por fragmento
shader-vertex-shader = shader de vértices
shader-fragment-shader = shader de fragmentos

## sheets

exercise-modelview = girar { $degrees } graus em torno de { $axis }, depois transladar { $translation }
exercise-name = exercício { $number } (semente { $seed })
sheet-rules-worksheet = as regras da lista (sem ambiente da cena, sem emissão, a própria M para as normais)
sheet-rules-opengl = as regras da função fixa do OpenGL 2.1
sheet-rules-demo = as regras do shader da demo de Phong
sheet-compute = Calcule a cor do vértice passo a passo, segundo { $rules }.
sheet-colours = As cores são escritas como na lista, [r g b 0], por isso cada produto de duas cores tem 0 como quarta componente.
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

exam-modelview = girar em torno de { $axis } pelo ângulo de cosseno { $cos } e seno { $sin }, depois transladar { $translation }
exam-name = exercício de prova { $number } (semente { $seed })
exam-material = escolhido para esta prova
exam-no-calculator = Sem calculadora.
exam-by-hand = Todos os valores se calculam à mão e de forma exata: use cada um exato no passo seguinte e arredonde só o valor que você escreve.
moodle-digits-quiz = Cada campo pede os algarismos significativos entre parênteses; uma resposta a menos de { $percent } % do valor (ou { $near_zero } perto de 0) está certa.
moodle-digits-exam = Informe cada valor arredondado para { $digits } algarismos significativos.
moodle-carry = Use cada valor no passo seguinte do jeito que você calculou, sem arredondar: arredonde só o que você digita num campo.
moodle-decimal-mark = Os números podem ser digitados com vírgula ou com ponto decimal: o Moodle aceita os dois.
moodle-part-digits = { $digits ->
    [0] { $digits } algarismos significativos
    [one] um algarismo significativo
   *[other] { $digits } algarismos significativos
}
moodle-right = Certo: { $formula }
moodle-picture-feedback = A imagem da esquerda está desenhada com { $right }; a da direita com { $wrong }.
moodle-wrong = Não está certo. { $formula }; o que entra no cálculo: { $inputs }; confira esses valores primeiro.
moodle-front-side = A iluminação é das duas faces: calcule a face da frente, aquela para onde aponta a normal do vértice (a de trás usa -n).
moodle-takes-givens = os dados
moodle-general-feedback = O feedback de cada campo dá a fórmula do seu passo; o cálculo completo de cada passo está no gabarito desta variante, que o professor tem.
moodle-picture-right = Desenhada corretamente
moodle-picture-wrong = Desenhada com um erro
moodle-picture-question = Que erro produz a imagem da direita?
moodle-choice-not = Não é este. Esse erro mudaria a imagem de outro jeito: { $why }

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
probe-pixel = Pixel ({ $x }, { $y }), { $shading }
probe-triangle = triângulo { $triangle }, vértices { $a }, { $b }, { $c }
probe-front-face = face da frente (sentido anti-horário na tela)
probe-back-face = face de trás (sentido horário na tela)
probe-weights = Pesos corrigidos pela perspectiva
probe-vertex-colours = Cores dos vértices (cada uma limitada no seu vértice, como o OpenGL faz)
probe-vertex-colours-unclamped = Cores dos vértices (uma varying de shader: sem limitar)
probe-vertex = vértice { $vertex }
probe-weighted-sum = Soma ponderada
probe-normal-interpolated = Normal interpolada, antes de normalizar
probe-normal-length = seu comprimento
probe-normal = Normal com que o fragmento é iluminado
probe-normal-as-interpolated = Normal usada como interpolada (este shader não a normaliza)
probe-position = Posição interpolada (espaço do olho)
probe-flat-centroid = Face iluminada uma vez, no seu centroide (espaço do olho)
probe-flat-normal = com a normal do seu plano
probe-provoking = O GL_FLAT do OpenGL usaria a cor do último vértice, o vértice { $vertex }
probe-terms = Termos no pixel
probe-terms-interpolated = Termos no pixel (os dos vértices, interpolados)
probe-light = Luz { $index }
probe-terms-sum = Soma dos termos (sem limitar)
probe-unclamped = Cor que chegou ao framebuffer
probe-stored = Armazenada, limitada e arredondada para 8 bits
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
write-kept-staging = nada foi apagado: os arquivos que não puderam voltar ao seu lugar ficaram na pasta de trabalho do phonglab lá dentro (.phonglab-set…), e a próxima execução nesta pasta os repõe ou diz onde estão

## errors

error-out-of-range = { $field } = { $value } está fora do intervalo: permitido { $allowed }
error-not-finite = { $field } precisa ser um número finito, não { $value }
error-too-many-lights = { $count } luzes: o OpenGL tem no máximo { $max }
error-camera-mismatch = a matriz de vista da cena não é a que a sua câmera dá ({ $camera }): defina a câmera, ou dê a matriz como câmera digitada
error-zero-attenuation = { $field }: as atenuações constante, linear e quadrática são todas 0, por isso a luz seria infinitamente brilhante; torne pelo menos uma positiva
allowed-spot-cutoff = [0, 90], ou 180 para não haver foco
allowed-float = um float: 0, ou 1,2e-38 <= |x| <= 3,4e38
allowed-mview = 1, 2, 3, 4 ou 5
allowed-look-at = um olho afastado do centro, com o vetor para cima fora da direção de vista
allowed-pixel = pelo menos 1 pixel
toml-place = linha { $line }, coluna { $column }
toml-unknown-field = campo desconhecido { $field }; os campos aceitos são { $known }
toml-did-you-mean = você quis dizer { $field }?
toml-missing-field = falta o campo { $field }
toml-invalid-type = tipo inválido: { $found }, esperava-se { $expected }
toml-kind-number = um número
toml-kind-number-value = o número { $value }
toml-kind-text = o texto { $value }
toml-kind-a-text = um texto (entre aspas)
toml-kind-boolean = true ou false
toml-camera-takes = { $field }: uma câmera do tipo kind = "{ $kind }" aceita { $keys }
toml-camera-needs = camera: kind = "{ $kind }" precisa de { $keys }
toml-unknown-material = { $field }: material desconhecido { $name }; os materiais clássicos são { $names }
toml-placement-needs-matrix = { $field }: placement = "matrix" precisa de placement_matrix (4 linhas de 4)
toml-matrix-needs-placement = { $field }: placement_matrix precisa de placement = "matrix"
toml-control-character = { $field } contém o caractere de controle { $char } (caractere { $position }): um nome ou um caminho é uma linha de texto imprimível
toml-unknown-field-one = campo desconhecido { $field }; o campo aceito é { $known }

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
why-position-translation = P = p + t; a modelview é uma translação (a sua parte 3x3 é a identidade), por isso os produtos das linhas e a divisão por w são pulados: três somas
why-position-affine = P = M p; a modelview é afim (última linha 0 0 0 1), por isso w = 1 e a divisão por w é pulada
why-position-projective = P = M p / w: a modelview é projetiva, w varia de vértice para vértice
why-position-eye = os vértices chegam no espaço do olho: nada a transformar
why-position-unread = nenhuma luz pontual e V é uma constante (observador no infinito): nada lê P
why-v-local = observador local: V = normalize(-P) por vértice, em f64; um bloco de { $chunk } vértices cujas coordenadas estão todas entre 2^-400 e 2^400 pula a mudança de escala por potências de dois antes de elevar ao quadrado (aí não muda nenhum bit)
why-v-worksheet = o V da lista = normalize(obs - P), obs = P (1, 1, 0, 1): (0, 0, -sinal(P.z)) por vértice
why-v-infinite = observador no infinito: V = (0, 0, 1) para todos os vértices
why-scene-added = somado como uma constante por face
why-scene-zero = ambos são zero (ou as regras os deixam de fora): nada é somado
why-two-sided = iluminação das duas faces: -n e o material do verso
why-one-sided = iluminação de uma face: a cor de trás é a da frente
why-l-positional = luz pontual: por vértice, em f64; um bloco de { $chunk } vértices cujas componentes de VP estão todas entre 2^-400 e 2^400 pula a mudança de escala por potências de dois antes de elevar ao quadrado (aí não muda nenhum bit)
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

## phonglab diagnose: a imagem de um aluno conferida

diagnose-normalize-off = GL_NORMALIZE deixado desligado com uma modelview que escala: as normais não têm comprimento 1
diagnose-viewer-swapped = O observador local e o observador no infinito trocados (GL_LIGHT_MODEL_LOCAL_VIEWER ao contrário)
diagnose-flipped-normals = As normais apontam para dentro (invertidas)
diagnose-two-sided-off = A iluminação das duas faces desligada: as faces de trás são iluminadas com as normais da frente
diagnose-two-sided-on = A iluminação das duas faces ligada onde a cena a tem desligada (GL_LIGHT_MODEL_TWO_SIDE verdadeiro): as faces de trás são iluminadas com as próprias normais e o material de trás, não com os da frente
diagnose-attenuation-left-out = A atenuação esquecida
diagnose-spot-left-out = O cone do spot esquecido (corte em 180)
# diagnose: picture mistakes
diagnose-shininess-fraction = O brilho dado como o valor de 0 a 1 de uma tabela de materiais em vez desse valor vezes 128 ({ $fraction } em vez de { $shininess-given }): um brilho espalhado pelo objeto todo
diagnose-light-left-out = A luz { $light } (GL_LIGHT{ $light }) esquecida: falta o glEnable(GL_LIGHT{ $light })
diagnose-point-as-directional = A luz { $light } (GL_LIGHT{ $light }) com w = 0 no GL_POSITION: uma luz direcional em vez de uma luz pontual
diagnose-light-ambient-left-out = A cor ambiente da luz { $light } (GL_LIGHT{ $light }) deixada no valor padrão do OpenGL (0, 0, 0, 1)
diagnose-specular-left-out = A cor especular do material deixada no valor padrão do OpenGL (0, 0, 0, 1): sem brilho
diagnose-diffuse-specular-swapped = As cores difusa e especular do material trocadas
diagnose-emission-added = Uma cor constante, cerca de { $emission }, somada onde o objeto está iluminado ou não: uma emissão (GL_EMISSION) que a cena não tem, ou mais luz ambiente
diagnose-colours-differ = As cores da imagem são as de outros valores (em cada termo, a cor da luz vezes a do material): { $terms }
diagnose-term-scene = a luz igual em toda parte (a ambiente da cena e a ambiente de cada luz sem atenuação nem spot, vezes o ambiente do material, mais a emissão)
diagnose-term-ambient = a ambiente de GL_LIGHT{ $light }
diagnose-term-diffuse = a difusa de GL_LIGHT{ $light }
diagnose-term-specular = a especular de GL_LIGHT{ $light }
diagnose-term-differs = { $term }: { $shown } na imagem, { $scene } na cena
diagnose-materials-differ = Os materiais da imagem têm outras cores que os da cena em uma das faces (iluminação das duas faces, cada face com o seu material): { $colours }
diagnose-side-front = da frente
diagnose-side-back = de trás
diagnose-material-colour-differs = { $name } { $which }: { $shown } na imagem, { $scene } na cena
diagnose-material-shininess-differs = GL_SHININESS { $which }: { $shown } na imagem, { $scene } na cena
diagnose-spot-cutoff-doubled = O corte do spot da luz { $light } (GL_LIGHT{ $light }) dobrado: foi dado o ângulo total do cone onde GL_SPOT_CUTOFF recebe a metade dele
diagnose-normal-matrix-not-transposed = As normais transformadas pela inversa da 3x3 da modelview (np.linalg.inv(m3)) onde o OpenGL usa a inversa transposta: sob uma rotação elas giram para o lado errado
diagnose-normal-not-transformed = As normais deixadas no espaço do objeto (sem a matriz das normais da modelview): o objeto é iluminado como se não tivesse girado
diagnose-depth-test-off = O teste de profundidade ficou de fora (falta glEnable(GL_DEPTH_TEST)): cada triângulo cobre os desenhados antes dele, então o lado de trás do objeto aparece por cima do da frente onde é desenhado depois
diagnose-quadric-inside = A quádrica virada do avesso (gluQuadricOrientation(GLU_INSIDE)): as normais apontam para dentro e as faces ficam voltadas para dentro, então o lado iluminado fica do lado oposto ao da luz
diagnose-light-after-model-light = A luz { $light } (GL_LIGHT{ $light }) dada com a matriz modelview com que o objeto é desenhado (visão × modelo) em vez da sua própria: ela se move com o objeto
diagnose-spot-cutoff-differs = O corte do spot da luz { $light } (GL_LIGHT{ $light }, GL_SPOT_CUTOFF) parece ser { $cutoff }° na imagem; a cena dá { $cutoff-scene }°
diagnose-spot-exponent-differs = O expoente do spot da luz { $light } (GL_LIGHT{ $light }, GL_SPOT_EXPONENT) parece ser { $exponent } na imagem; a cena dá { $exponent-scene }
diagnose-attenuation-constant-differs = A atenuação constante da luz { $light } (GL_LIGHT{ $light }, GL_CONSTANT_ATTENUATION) parece ser { $constant } na imagem; a cena dá { $constant-scene }
diagnose-attenuation-linear-differs = A atenuação linear da luz { $light } (GL_LIGHT{ $light }, GL_LINEAR_ATTENUATION) parece ser { $linear } na imagem; a cena dá { $linear-scene }
diagnose-attenuation-quadratic-differs = A atenuação quadrática da luz { $light } (GL_LIGHT{ $light }, GL_QUADRATIC_ATTENUATION) parece ser { $quadratic } na imagem; a cena dá { $quadratic-scene }
diagnose-shininess-differs = O brilho (GL_SHININESS) parece ser { $shininess } na imagem; a cena dá { $shininess-scene }
diagnose-value-negligible = { $least } ou mais (a luz é desprezível: nada dela chega ao objeto)
diagnose-attenuation-left-out-light = A atenuação da luz { $light } (GL_LIGHT{ $light }) esquecida
diagnose-spot-direction-untransformed = A direção do spot da luz { $light } (GL_LIGHT{ $light }) dada antes da transformação da câmera (com a identidade), e a posição dela depois
diagnose-light-after-model = As luzes colocadas no mundo dadas depois da transformação de modelo (com visão × modelo em vez da visão): elas giram com o objeto
diagnose-headlight-under-view = A luz { $light } (GL_LIGHT{ $light }), presa ao olho, dada com a transformação de visão em vez da identidade: fica colocada no mundo
diagnose-light-before-view-light = A luz { $light } (GL_LIGHT{ $light }) colocada antes da câmera: o GL_POSITION dela dado com a identidade e não com a transformação de visão, por isso ela se move com o olho
diagnose-colour-material-off = GL_COLOR_MATERIAL não ativado: o objeto é iluminado com as cores do glMaterial, não com a cor corrente
diagnose-colour-material-diffuse-only = O glColorMaterial acompanhando só GL_DIFFUSE em vez de GL_AMBIENT_AND_DIFFUSE: a cor ambiente continua a do glMaterial
diagnose-spot-cutoff-halved = O corte do spot da luz { $light } (GL_LIGHT{ $light }) pela metade: foi dado o ângulo total do cone onde GL_SPOT_CUTOFF recebe a metade dele
diagnose-spot-cutoff-radians = O corte do spot da luz { $light } (GL_LIGHT{ $light }) dado em radianos (math.radians): o OpenGL recebe GL_SPOT_CUTOFF em graus
diagnose-spot-exponent-ignored = O expoente do spot da luz { $light } (GL_LIGHT{ $light }) esquecido (0): um círculo de luz de borda nítida
diagnose-spot-cutoff-exponent-swapped = O corte e o expoente do spot da luz { $light } (GL_LIGHT{ $light }) trocados
diagnose-spot-direction-reversed = A direção do spot da luz { $light } (GL_LIGHT{ $light }) invertida: aponta do alvo para a luz
diagnose-attenuation-terms-swapped = As atenuações linear e quadrática da luz { $light } (GL_LIGHT{ $light }) trocadas
diagnose-attenuation-constant-left-out = A atenuação constante da luz { $light } (GL_LIGHT{ $light }) zerada (como se 0 quisesse dizer sem atenuação)
diagnose-directional-as-point = A luz { $light } (GL_LIGHT{ $light }) com w = 1 no GL_POSITION: uma luz pontual em vez de uma luz direcional
diagnose-diffuse-back-only = A cor difusa do material dada só para GL_BACK: as faces da frente ficam com o valor padrão do OpenGL (0,8, 0,8, 0,8)
diagnose-ambient-back-only = A cor ambiente do material dada só para GL_BACK: as faces da frente ficam com o valor padrão do OpenGL (0,2, 0,2, 0,2)
diagnose-specular-back-only = A cor especular e o brilho do material dados só para GL_BACK: as faces da frente ficam com os valores padrão do OpenGL (sem brilho)
diagnose-material-back-only = Todas as chamadas glMaterial dadas só para GL_BACK: as faces da frente ficam com o material padrão do OpenGL
diagnose-light-colour-0-255 = A cor difusa da luz { $light } (GL_LIGHT{ $light }) dada de 0 a 255 em vez de 0 a 1
diagnose-row-vectors = A matriz modelview das luzes carregada transposta (as linhas do NumPy passadas ao glLoadMatrixf como colunas)
diagnose-light-ambient-from-diffuse = A cor ambiente da luz { $light } (GL_LIGHT{ $light }) copiada da cor difusa dela
diagnose-ambient-from-diffuse = A cor ambiente do material igual à cor difusa dele (GL_AMBIENT_AND_DIFFUSE)
diagnose-specular-from-colour = A cor especular do material igual à cor do objeto: um brilho colorido
diagnose-emission-left-out = A emissão do material deixada em preto (0, 0, 0, 1)
diagnose-row-vectors-light = A matriz modelview da luz { $light } (GL_LIGHT{ $light }) carregada transposta (as linhas do NumPy passadas ao glLoadMatrixf como colunas)
diagnose-emission-from-colour = A emissão do material igual à cor do objeto: o objeto brilha com a própria cor
diagnose-ambient-diffuse-swapped = As cores ambiente e difusa do material trocadas
diagnose-light-diffuse-left-out = A cor difusa da luz { $light } (GL_LIGHT{ $light }) nunca definida: o valor padrão do OpenGL, branco para GL_LIGHT0 e preto para as outras
diagnose-diffuse-not-clamped = No shader, o termo difuso usa N·L sem max(N·L, 0): onde a luz está atrás da superfície, ele subtrai luz
diagnose-vlv-reversed = No shader, o vetor da luz L aponta da luz para a superfície (P − posição da luz) em vez de apontar da superfície para a luz
diagnose-viewer-reversed = No shader, o V do observador local aponta do olho para o ponto (normalize(P)) em vez de apontar para o olho (normalize(−P))
diagnose-halfway-not-normalised = No shader, o vetor médio L + V não é normalizado antes do produto escalar com N
diagnose-flat-shade-model = glShadeModel(GL_FLAT) em vez de GL_SMOOTH: cada face tem uma cor só, a cor calculada no seu último vértice
diagnose-view-order-reversed = A modelview do objeto multiplicada na ordem errada (rotação × translação em vez de translação × rotação): o objeto é desenhado e iluminado fora do lugar
diagnose-view-order-reversed-lights = A matriz de visualização multiplicada na ordem errada (rotação × translação em vez de translação × rotação), para o objeto e para as luzes posicionadas com ela
diagnose-view-order-reversed-lights-only = A matriz de visualização das luzes multiplicada na ordem errada (rotação × translação em vez de translação × rotação): as luzes posicionadas no mundo ficam no lugar errado; o objeto é desenhado certo
diagnose-shininess-refused = GL_SHININESS dado acima de 128 (um valor de 0 a 1 multiplicado por 128 duas vezes, ou em uma escala de 0 a 1000): o OpenGL recusa a chamada (GL_INVALID_VALUE) e o brilho fica no valor padrão, 0: a cor especular espalhada por todo o lado iluminado
diagnose-directional-reversed = A direção da luz { $light } (GL_LIGHT{ $light }) invertida: o GL_POSITION (x, y, z, 0) dado como a direção em que a luz se propaga em vez da direção que aponta para a luz, então o objeto é iluminado pelo lado oposto
diagnose-scene-ambient-default = A luz ambiente da cena (glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ...)) nunca definida: o valor padrão do OpenGL (0,2, 0,2, 0,2, 1)
diagnose-light-specular-left-out = A cor especular da luz { $light } (GL_LIGHT{ $light }) nunca definida: o valor padrão do OpenGL, branco para GL_LIGHT0 e preto para as outras
diagnose-light-ambient-diffuse-swapped = As cores ambiente e difusa da luz { $light } (GL_LIGHT{ $light }) trocadas
diagnose-light-diffuse-on-previous = A cor difusa da luz { $light } passada para GL_LIGHT{ $previous } (um bloco copiado em que o número da luz não foi trocado): GL_LIGHT{ $previous } recebe essa cor e GL_LIGHT{ $light } fica com o valor padrão do OpenGL
diagnose-light-specular-on-previous = A cor especular da luz { $light } passada para GL_LIGHT{ $previous } (um bloco copiado em que o número da luz não foi trocado): GL_LIGHT{ $previous } recebe essa cor e GL_LIGHT{ $light } fica com o valor padrão do OpenGL
diagnose-positions-as-normals = As posições dos vértices passadas como normais (glNormal3fv(posição)): cada normal aponta a partir do centro do objeto e seu comprimento é a distância do ponto (o raio, em uma esfera), o que ilumina errado sem GL_NORMALIZE
diagnose-colour-material-ambient-and-diffuse = O glColorMaterial acompanhando GL_AMBIENT_AND_DIFFUSE em vez de só GL_DIFFUSE: a cor corrente substitui também a cor ambiente do material
diagnose-colour-material-wrong-face = O glColorMaterial dado para a face errada (GL_BACK em vez de GL_FRONT, ou o contrário): as faces visíveis ficam com as cores do glMaterial em vez da cor corrente
diagnose-spot-cutoff-cosine = O corte do spot da luz { $light } (GL_LIGHT{ $light }) dado como seu cosseno (math.cos(math.radians(…)), cerca de 0,99): o OpenGL recebe GL_SPOT_CUTOFF em graus, então o cone tem menos de um grau
diagnose-material-front-only = Iluminação das duas faces com as chamadas glMaterial dadas só para GL_FRONT: as faces de trás ficam com o material padrão do OpenGL
diagnose-emission-back-only = A emissão do material dada só para GL_BACK: as faces da frente ficam com o valor padrão do OpenGL, preto
diagnose-material-diffuse-0-255 = A cor difusa do material dada de 0 a 255 em vez de 0 a 1 ({ $diffuse-levels } em vez de { $diffuse-given }): o termo difuso satura onde quer que a luz chegue
diagnose-material-colours-0-255 = As cores do material (ambiente, difusa, especular) dadas de 0 a 255 em vez de 0 a 1: o objeto satura
diagnose-light-not-normalised = No shader, o L de uma luz pontual não é normalizado (L = luz − P sem dividir pelo seu comprimento d): N·L e o cosseno do spot crescem com a distância
diagnose-reflection-reversed = No shader, R refletido ao contrário (reflect(L, N) em vez de reflect(-L, N)): o brilho aparece do lado oposto ao certo
diagnose-rescale-for-normalize = GL_RESCALE_NORMAL ativado onde é necessário GL_NORMALIZE: com uma escala não uniforme as normais são reescaladas mas não ficam com comprimento 1
diagnose-same-picture = Essas causas desenham a mesma imagem, então não dá para distingui-las por ela (as mais comuns primeiro): { $ids }. Confira qual delas está no programa.
diagnose-same-picture-fitted = Essas causas desenham a mesma imagem, então não dá para distingui-las por ela (as mais comuns primeiro, um valor alterado antes de um valor ajustado à imagem): { $ids }. Confira qual delas está no programa.
diagnose-light-unseen = Nada da luz { $light } (GL_LIGHT{ $light }) chega ao objeto: a imagem é a cena iluminada sem ela.
diagnose-nothing-drawn = nada do objeto está desenhado: a imagem é só o fundo. Verifique a chamada que o desenha (glutSolidTeapot, gluSphere…) e se ela é executada, e a câmera (gluLookAt, gluPerspective): o objeto pode estar atrás dela ou fora do seu campo de visão.
diagnose-outline-differs = o contorno do objeto não é o desta cena ({ $share } dele difere, além de um pixel): esta é a imagem desta cena? Verifique --scene, e o objeto e a câmera do programa.
diagnose-region-differs = uma região de { $pixels } pixels em torno de ({ $x }, { $y }) difere da imagem certa (a imagem certa explica { $score } dos pixels do objeto): há algo desenhado sobre o objeto ali, ou essa parte dele está errada. Confira o que o programa desenha depois do objeto, e a iluminação dessa parte (as normais, o material).
diagnose-offset-darker = os { $pixels } pixels do objeto de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 }) estão uniformemente mais escuros do que na imagem certa, { $levels } níveis em média (o ruído, uma imagem salva com perdas ou um pixel de deslocamento deixam menos de { $least }) (a imagem certa explica { $score } dos pixels do objeto): algo foi pintado sobre o objeto ali, ou a luz ou o material dele estão um pouco errados. Verifique o que o programa desenha depois do objeto e compare os valores de glLight*/glMaterial* do programa com os da cena.
diagnose-offset-lighter = os { $pixels } pixels do objeto de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 }) estão uniformemente mais claros do que na imagem certa, { $levels } níveis em média (o ruído, uma imagem salva com perdas ou um pixel de deslocamento deixam menos de { $least }) (a imagem certa explica { $score } dos pixels do objeto): algo foi pintado sobre o objeto ali, ou a luz ou o material dele estão um pouco errados. Verifique o que o programa desenha depois do objeto e compare os valores de glLight*/glMaterial* do programa com os da cena.
diagnose-marks-differ = marcas finas de { $pixels } pixels, de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 }), diferem da imagem certa (a imagem certa explica { $score } dos pixels do objeto): há linhas ou marcas desenhadas sobre o objeto ali. Confira o que o programa desenha depois do objeto (texto, eixos, um cursor), e salve o PNG dele antes de desenhar algo por cima.
diagnose-levels-darker = a imagem inteira está, em média, { $levels } níveis mais escura que a certa, e a imagem certa com os níveis assim mudados a explica tão bem quanto qualquer erro ({ $score } dos pixels do objeto). Uma mudança do gama, do brilho ou do perfil de cor da imagem salva faz isso, e um erro na iluminação pode se esconder por baixo: salve o PNG do programa sem alterá-lo (com a opção --png) e verifique-o de novo.
diagnose-levels-lighter = a imagem inteira está, em média, { $levels } níveis mais clara que a certa, e a imagem certa com os níveis assim mudados a explica tão bem quanto qualquer erro ({ $score } dos pixels do objeto). Uma mudança do gama, do brilho ou do perfil de cor da imagem salva faz isso, e um erro na iluminação pode se esconder por baixo: salve o PNG do programa sem alterá-lo (com a opção --png) e verifique-o de novo.
diagnose-footprint = Esse erro muda a imagem certa em no máximo { $most } níveis; em mais de { $tolerance } níveis, além do deslocamento de um pixel, só em { $pixels } pixels: { $groups }. São poucos demais para a porcentagem mostrá-lo; ali a sua imagem é a do erro: ela está, em média, a { $mistake } níveis da imagem com o erro e a { $right } da imagem certa.
diagnose-footprint-group = { $count } de ({ $x0 }, { $y0 }) a ({ $x1 }, { $y1 })
diagnose-footprint-rest = { $count } em outros lugares
diagnose-footprint-and = e
diagnose-verdict-right-lossy = Certa, com perdas: a imagem certa explica { $score } dos pixels do objeto a menos de { $levels } níveis de uma mistura dos seus vizinhos ({ $strict } a menos de { $tolerance } de um vizinho), e o que difere é ruído (como o deixado por um JPEG, um redimensionamento, um desfoque ou uma câmera), não uma mudança que a imagem mostre. Um valor um pouco errado (um expoente do spot 9 em vez de 8) pode se esconder nas perdas; os números que o programa imprime mostram isso (phonglab check).
diagnose-looks-jpeg = A imagem parece ter sido salva como JPEG: a diferença dela para a imagem certa salta nas bordas de blocos de 8 x 8 ({ $ratio } vezes mais do que dentro deles). Salvar com perdas muda um pouco cada pixel e pode esconder a causa: salve a imagem como PNG direto do programa (com a opção --png do programa exportado) e diagnostique essa.
diagnose-evenly-off = A imagem não é a certa apenas com perdas: nos { $width } x { $width } pixels a partir de ({ $x0 }, { $y0 }) o { $channel ->
        [0] vermelho
        [1] verde
       *[2] azul
    } dela difere do da imagem certa { $levels } níveis em média, { $errors } erros-padrão além do que um deslocamento de meio pixel faz ali; o ruído e uma imagem salva com perdas espalham essa média em torno de 0. Um valor da cena (uma cor, uma atenuação, o brilho) pode estar um pouco errado ali, ou a imagem deslocada mais de meio pixel, e as perdas podem esconder qual: salve a imagem como PNG direto do programa (com a opção --png do programa exportado) e diagnostique essa.
diagnose-verdict-right-within = Certa, até onde uma imagem permite dizer: a imagem certa explica { $score } dos pixels do objeto (com um pixel de deslocamento e { $tolerance } níveis de tolerância), mas dentro do objeto a sua imagem difere dela em até { $most } níveis, { $pixels } pixels em mais de { $rounding }. Um erro que não mude a imagem mais do que isso (um brilho ou uma cor um pouco diferentes) tem a mesma aparência: este veredito não o descarta. Os números do programa descartam: verifique os valores que o notebook imprime com o phonglab check, ou compare os valores de glLight*/glMaterial* do programa com os da cena.
diagnose-verdict-right = Certa: a imagem certa explica { $score } dos pixels do objeto e, dentro do objeto, a sua é essa imagem até o arredondamento ({ $rounding } nível), como outro OpenGL a desenha. Um valor tão pouco errado que não mude nenhum pixel mais do que isso não aparece em uma imagem; os números que o programa imprime mostram isso (phonglab check).
diagnose-verdict-wrong = Errada. A causa: { $cause } ({ $id }); a imagem com esse erro explica { $score } dos pixels do objeto, a imagem certa { $right }.
diagnose-verdict-wrong-nearer = Errada. A causa: { $cause } ({ $id }). A imagem com esse erro e a imagem certa explicam ambas { $score } dos pixels do objeto dentro da tolerância, mas onde as duas diferem ({ $pixels } pixels) a sua fica, em média (quadrática), a { $fitted } níveis da primeira e a { $scene } da certa.
diagnose-verdict-wrong-nearer-inside = Errada. A causa: { $cause } ({ $id }). A imagem com esse erro e a imagem certa explicam ambas { $score } dos pixels do objeto dentro da tolerância, mas dentro do objeto a sua fica, em média, a { $fitted } níveis da primeira (somados os três canais) e a { $scene } da certa.
diagnose-verdict-wrong-or = Errada. A causa: { $cause } ({ $id }) ou { $other } ({ $other-id }){ $more ->
        [0] {""}
        [one] , ou mais uma, listada abaixo
       *[other] , ou uma de mais { $more }, listadas abaixo
    }: a imagem não permite dizer qual; cada um desses erros explica { $score } dos pixels do objeto, a imagem certa { $right }.
diagnose-unexplained-said = Não explicada: { $finding }
diagnose-difference-said = |A − B| de cada canal × { $gain }: preto onde as duas imagens coincidem, intensidade máxima (255) a partir de uma diferença de { $full } { $full ->
        [0] níveis
        [one] nível
       *[other] níveis
    }; a maior diferença aqui, { $largest } { $largest ->
        [0] níveis
        [one] nível
       *[other] níveis
    }, é desenhada em { $drawn }/255{ $boxes ->
        [0] .
        [one] . Uma caixa tracejada em magenta marca o lugar que o diagnóstico aponta.
       *[other] . Caixas tracejadas em magenta marcam os { $boxes } lugares que o diagnóstico aponta.
    }
diagnose-also = Também explica a imagem: { $cause } ({ $id }), { $score }.
diagnose-verdict-unexplained = Nenhum erro que o phonglab conheça explica esta imagem: a imagem certa explica { $right } dos pixels do objeto. O erro mais próximo, que não é apontado como a causa ({ $id }, { $score }): { $cause }.
diagnose-verdict-unexplained-none = Nenhum erro que o phonglab conheça explica esta imagem: a imagem certa explica { $right } dos pixels do objeto.
diagnose-where = Os pixels são contados a partir de (0, 0) no canto superior esquerdo, com y para baixo, como as linhas do PNG (o glReadPixels conta a partir do canto inferior esquerdo).

## phonglab check: o trabalho de um aluno verificado

check-no-outputs = este notebook foi salvo sem as saídas: não há nada impresso para verificar. Execute-o primeiro (Jupyter: Kernel → Restart & Run All), salve e verifique de novo
check-too-many-values = este trabalho imprime mais de { $count } números: ele é recusado por inteiro em vez de verificado só em parte (imprima só os passos da lista de exercícios)
check-verdict-right = certo
check-verdict-right-given = certo, dado o seu { $step }
check-verdict-rounding = arredondamento
check-verdict-wrong = errado
check-cause-normal-by-modelview = a normal transformada pela modelview M em vez da sua inversa transposta (errado com uma escala não uniforme)
check-cause-normal-not-normalised = a normal não normalizada depois de transformada
check-cause-light-not-transformed = a posição da luz não transformada pela modelview (ficou no espaço do objeto)
check-cause-light-transformed-twice = a posição da luz transformada duas vezes pela modelview
check-cause-vectors-cell-run-twice = a normal parece transformada duas vezes, e o vértice e a luz junto: a célula que os transforma foi executada duas vezes. Reinicie e execute tudo (Jupyter: Kernel → Restart & Run All)
check-cause-vlv-reversed = vlv invertido: da luz para o vértice em vez do vértice para a luz
check-cause-vlv-not-normalised = vlv não normalizado
check-cause-directional-as-point = uma luz direcional (w = 0) tratada como pontual
check-cause-viewer-swapped = o observador local e o observador no infinito trocados
check-cause-halfway-not-normalised = H não normalizado
check-cause-specular-without-gate = especular calculada onde a luz está atrás da superfície (falta a condição N·L)
check-cause-diffuse-not-clamped = a difusa não limitada: negativa quando o ângulo passa de 90 graus
check-cause-acos-past-one = acos de um cosseno um pouco acima de 1 (arredondamento): limite-o antes a [-1, 1]
check-cause-spot-cutoff-radians = o cosseno do ângulo de corte do spot calculado em graus como se fossem radianos
check-cause-spot-exponent-outside-cone = o expoente do spot aplicado também fora do cone
check-cause-attenuation-multiplied = a luz multiplicada pela atenuação em vez de dividida
check-cause-attenuation-object-distance = a distância da atenuação medida no espaço do objeto
check-cause-w-divide-forgotten = faltou a divisão por w
check-cause-shininess-fraction = o brilho como fração de 0 a 1 em vez de multiplicado por 128
check-cause-for-light = { $cause } (luz { $light })
check-cause-normal-matrix-with-translation = a normal transformada pela inversa transposta da modelview 4x4 inteira: a translação dá à normal um w que entra no seu comprimento
check-cause-normal-not-transformed = a normal não transformada para o espaço do olho
check-cause-vertex-not-transformed = a posição do vértice não transformada pela modelview (ficou no espaço do objeto)
check-cause-point-as-directional = uma luz pontual tratada como direcional: vlv tirado só da sua posição
check-cause-viewer-reversed = vov ao contrário: do olho para o vértice em vez do vértice para o olho
check-cause-light-ambient-left-out = faltou o termo ambiente da luz na sua contribuição
check-cause-ambient-times-cosine = o termo ambiente multiplicado por N·L como a difusa (a luz ambiente não tem direção)
check-cause-colours-mixed-up = uma cor do termo errado (ou nenhuma) em um produto: cada termo multiplica a cor da luz e a do material desse mesmo termo
check-cause-cos-theta-with-light-position = cosTheta calculado com a posição da luz em vez do vetor unitário vlv
check-cause-theta-in-degrees = o ângulo convertido para graus e comparado com pi/2 (radianos): a difusa desaparece acima de 1,57 graus
check-cause-reflection-for-halfway = o R·V de Phong usado onde o OpenGL usa o N·H de Blinn-Phong
check-cause-reflection-reversed = R ao contrário: L - 2(N·L)N em vez de 2(N·L)N - L
check-cause-specular-cosine-not-clamped = o cosseno especular não limitado a 0 antes da potência
check-cause-specular-left-out = faltou o termo especular na contribuição da luz
check-cause-attenuation-left-out = a contribuição da luz não dividida pela atenuação
check-cause-ambient-not-attenuated = o termo ambiente da luz não dividido pela atenuação (o OpenGL atenua o ambiente, a difusa e a especular da mesma forma)
check-cause-attenuation-constant-left-out = faltou o termo constante da atenuação
check-cause-attenuation-quadratic-not-squared = o termo quadrático da atenuação multiplicado por d em vez de d²
check-cause-distance-from-normalised-vlv = a distância tirada do vlv já normalizado (sempre 1)
check-cause-distance-squared = a distância ao quadrado: faltou a raiz quadrada
check-cause-spot-exponent-ignored = faltou o expoente do foco: o fator do foco é o próprio cosseno
check-cause-cone-test-inverted = o teste do cone do foco invertido: iluminado fora do cone, escuro dentro
check-cause-spot-angle-reversed = o ângulo do foco medido com vlv (para a luz) em vez de -vlv (a partir da luz)
check-cause-spot-direction-untransformed = a direção do foco não transformada para o espaço do olho
check-cause-spot-left-out = o fator do foco não aplicado à contribuição da luz
check-cause-spot-on-whole-colour = o fator do foco aplicado à cor toda (também à emissão e ao ambiente da cena)
check-cause-light-left-out = faltou a contribuição de uma luz na soma
check-cause-scene-ambient-left-out = faltou o ambiente global da cena na soma
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
check-cause-spot-on-diffuse-only = o fator do foco aplicado só à difusa (o OpenGL o aplica à contribuição toda da luz)
check-cause-only-last-light = só a contribuição da última luz na soma (a variável do laço usada depois do laço)
check-cause-emission-left-out = faltou a emissão do material na soma
check-cause-alpha-from-sum = o alfa da cor tirado de uma quarta componente que é 0 nestas células (I[3], matDif[3]: as cores estão escritas [r g b 0]) em vez do alfa da difusa do material
check-cause-normal-as-point = a normal escrita com w = 1 (como um ponto): a translação a desloca
check-cause-light-by-mview = a luz transformada pela modelview do vértice, mview, em vez da que estava ativa quando foi posicionada (uma luz fixa no olho movida com a câmera)
check-cause-spot-cutoff-halved = o ângulo de corte tomado como o ângulo total do cone: usada metade
check-cause-spot-not-on-ambient = o fator do foco não aplicado ao termo ambiente da luz
check-cause-attenuation-on-whole-colour = a atenuação dividindo a cor toda (também a emissão e o ambiente da cena)
check-cause-attenuation-on-directional = uma luz direcional (w = 0) atenuada: o OpenGL não a atenua
check-cause-vov-with-w = vov = -vertexPos normalizado com seu w (-1) no comprimento: o vetor de visão é uma direção, seu w é 0
check-cause-specular-test-in-degrees = o teste do ângulo especular compara beta em radianos com 90 (graus): nunca corta a especular
check-cause-specular-times-cosine = a especular também multiplicada por N·L (só a difusa o é)
check-cause-shininess-as-product = o brilho como fator (cosBeta*ns) em vez de potência (cosBeta**ns)
check-cause-distance-without-w-divide = a distância calculada com a posição da luz sem dividir pelo seu w (o vlv divide)
check-cause-scene-ambient-wrong-material = o ambiente global da cena multiplicado pela cor difusa ou especular do material em vez da ambiente
check-cause-ambient-outside-share = o termo ambiente da luz fora do fator do foco e da atenuação
check-cause-scene-ambient-times-light = o ambiente global da cena também multiplicado pela cor ambiente da luz
check-cause-specular-of-diffuse-cosine = a potência especular calculada do cosseno difuso (cosTheta**ns) em vez de N·H
check-cause-spot-exponent-as-factor = o expoente do foco como fator (cosSpot*spotCoef) em vez de potência
check-cause-attenuation-inverted = a atenuação invertida (at = 1/(...)) e depois usada dividindo: a luz multiplicada pelo denominador
check-run-stopped = não verificado: a execução parou com um erro antes do fim: { $error }
check-nothing-compared = não verificado: nada do que você imprimiu é um passo da lista; imprima cada valor como a lista faz, print("vlv = ", vlv)
check-unreadable-steps = não verificado por inteiro: estes passos foram impressos com valores que não são números como o NumPy ou o Python os imprimem ({ $names }); imprima cada valor sozinho
check-missing-steps = não verificado: o notebook não tem valor para { $names }: uma célula não foi executada ou parou com um erro. Execute todas as células (Jupyter: Kernel → Restart & Run All) e depois esta
check-incomplete = incompleto: { $steps }
check-not-printed = a lista pede { $count ->
        [0] nenhum passo que este trabalho não imprima
        [one] um passo que este trabalho não imprime: { $names }
       *[other] { $count } passos que este trabalho não imprime, o primeiro { $first }: { $names }
    }. Execute todas as células (Jupyter: Restart & Run All, no menu Kernel), imprima cada passo como a lista faz (print("vlv = ", vlv)) e verifique de novo
check-stale-outputs = não verificado por inteiro: as saídas não são de uma única execução, em ordem (uma célula numerada [{ $later }] abaixo de uma numerada [{ $earlier }]: uma célula foi executada de novo, ou fora de ordem). Execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel), salve e verifique de novo
check-after-error = impresso depois do erro, portanto por uma execução anterior (o Run All para em um erro), e não verificado: { $names }
# fix57b
py-shade-model-comment = glShadeModel(GL_SMOOTH) desenha o sombreamento para o qual este programa foi escrito (Gouraud: as cores dos vértices interpoladas; Phong: cada pixel iluminado). Com GL_FLAT, os shaders desenham o que o OpenGL de pipeline fixo desenha: cada face na cor calculada no seu vértice provocante (o último vértice de um triângulo ou de um quadrilátero).
py-two-side-program-comment = Faz o gl_Color do fragment shader ser a cor de trás na face de trás de um triângulo, como o GL de pipeline fixo a escolhe; os shaders o usam com glShadeModel(GL_FLAT).
# phonglab-py: the Python package
python-unknown-value = { $what }{ $value }: os valores possíveis são { $names }
python-wrong-length = { $field }: { $count ->
        [0] { $count } números informados
        [one] 1 número informado
       *[other] { $count } números informados
    }, { $expected } esperados{ $hint }
python-hint-alpha = ; uma cor é r, g, b, a: acrescente o alfa, como [0.8, 0.2, 0.2, 1]
python-hint-w = ; a posição de uma luz é x, y, z, w: w = 1 para uma luz em um ponto, 0 para uma luz muito distante nessa direção, como [0, 0, 90, 1]
python-hint-normal = ; uma normal é uma direção: x, y, z, ou x, y, z, 0 como na lista (o w dela é 0)
python-hint-vertex = ; um vértice é x, y, z (o w fica 1) ou x, y, z, w
python-either-3-or-4 = 3 ou 4
python-no-such-light = não existe a luz { $light }: a cena tem { $count ->
        [0] nenhuma luz
        [one] 1 luz, numerada 0
       *[other] { $count } luzes, numeradas a partir de 0
    }
python-not-real = { $what } = { $value }: não é um número. Informe números reais: um int ou um float, ou uma lista ou array NumPy deles (um texto, True ou False, None e números complexos não são lidos como números; em Python escreva 25.6, não "25,6")
python-not-integer = { $what } = { $value }: não é um número inteiro; informe um int, por exemplo 5
python-not-a-scene = { $what }: { $value } não é uma phonglab.Scene; crie uma antes: phonglab.Scene.load("cena.toml"), phonglab.Scene.worksheet(5) ou phonglab.Scene.preset("phong-demo")
python-not-a-name = { $what } = { $value }: não é um texto; passe uma str, como scene.name = "câmera da mview3"
python-edit-fields = { $what } não é substituído por inteiro: edite os campos dele um por um, como { $example }
python-load-notebook = { $path } é um notebook ou um script, não um arquivo de cena: leia a cena que ele define com phonglab.Scene.from_notebook(caminho)
python-no-field-guess = { $what } não tem { $value }: você quis dizer { $guess }? Seus nomes: { $names }
python-no-field = { $what } não tem { $value }; seus nomes: { $names }
python-lights-fixed = scene.lights não tem { $value }: as luzes são as da cena, editadas aqui campo a campo (scene.lights[0].position = ...); uma luz é adicionada ou removida em um arquivo de cena, que o Scene.load depois lê
python-no-memory = memória insuficiente: não foi possível obter { $bytes } bytes; ilumine os vértices em blocos menores
python-check-reassigned = Observação: { $name } é atribuído de novo em uma célula executada depois da que o imprime, então a autoverificação lê o valor que { $name } tem agora, não o impresso (o phonglab check lê o impresso). Use outro nome ali, ou execute as células em ordem de novo.
python-overflow = { $step } dá { $value } em { $precision }: os números da cena passam do que o { $precision } guarda (float32: ±3,4e38), por isso a iluminação estoura; nada é retornado (precision="f64" guarda mais)
python-render-no-memory = memória insuficiente para desenhar uma imagem de { $size } x { $size }: ela precisa de cerca de { $bytes }, o dobro é pedido antes, e não foi possível obtê-lo; escolha um tamanho menor
python-not-finite-row = { $name }: a linha { $row } é { $value }: todos os números precisam ser finitos e estar dentro do intervalo do float32 (±3,4e38)
python-wrong-shape = { $name }: um array de formato { $shape }, quando se espera (N, 3), com o mesmo N para as posições e as normais
nb-self-check = Autoverificação: com o pacote Python phonglab instalado (ainda não está no PyPI: instale o arquivo wheel, `pip install phonglab-*.whl`, que o `scripts/wheel` do phonglab gera ou que o professor distribui), descomente a célula abaixo e execute-a depois das outras. Ela compara cada valor que este notebook calculou com o gabarito, passo a passo, e aponta o primeiro passo errado e a causa provável. Nada mais neste notebook depende dela.
check-rules = regras assumidas: { $rules }
check-inputs-differ = os dados que você digitou diferem dos do enunciado: { $names }
check-other-scene = { $count } dos dados que você digitou diferem dos do enunciado: esta é a cena certa (--scene)? Nenhuma causa é apontada para um trabalho digitado para outra cena
check-step = { $step }: o seu { $student }, o do gabarito { $key }: { $verdict }
check-first-wrong = primeiro passo errado: { $step } (o seu { $student }, o do gabarito { $key })
check-all-right = tudo certo: todos os passos impressos são os do gabarito
check-cause = causa provável: { $words } [{ $id }]. Evidência: em { $step }, você imprimiu { $student }, e o gabarito com esse erro dá { $value }
check-cause-formula = a fórmula com esse erro (um modelo dele, não o seu código): { $formula }
check-no-cause = nenhum erro do catálogo reproduz tudo o que você imprimiu; veja o primeiro passo errado
check-given-not-finite = não verificado: um dado não é um número finito ({ $givens })
check-printed-twice = impresso mais de uma vez, com valores diferentes (cada impressão é verificada): { $names }
check-input-rules = as regras
check-given-not-followed = não verificado: um dado é alterado no próprio lugar, o que a verificação não segue ({ $givens }): atribua-o inteiro em uma só linha
# py58b: the notebook's self-check, the worked calculation's table
python-check-no-cells = phonglab.check(globals()) confere um notebook Jupyter: lê as células já executadas do In do notebook, e este Python não tem isso. Para um script, salve o que ele imprime e confira isso: python3 script.py > impresso.txt, depois phonglab check --printed impresso.txt
python-check-run-first = ainda não há nada para conferir: nenhuma célula da lista foi executada neste kernel (também depois de reiniciá-lo). Execute antes as outras células (Run All) e depois esta
python-check-not-globals = o phonglab.check lê as variáveis do notebook: passe globals(), com os parênteses: phonglab.check(globals())
explain-column-step = passo
explain-column-formula = fórmula
explain-column-value = valor
explain-column-notes = observações
share-base-refused = a página que um link abre precisa ser um endereço http:// ou https://, sem espaços, aspas nem caracteres de controle: { $base }

## Files read and written (formats::files): shared by the command line, the window and the Python package

io-folder-missing = a pasta { $folder } não existe: crie-a antes, ou indique um arquivo em uma pasta que exista
io-not-found = não existe
io-permission-denied = sem permissão
io-storage-full = o disco está cheio
io-open-elsewhere = outro programa está com ele aberto (feche-o lá e tente de novo)
io-handle-lost = o sistema perdeu o rastro de um arquivo ou pasta que o phonglab tinha aberto: uma pasta em que trabalhava foi renomeada ou substituída por um link enquanto escrevia (no Wine, por um programa fora do Wine)
io-link-in-the-way = há um link no caminho (posto lá, ou mudado enquanto o phonglab escrevia): aqui o phonglab nunca segue um
io-is-a-directory = é uma pasta
io-not-a-directory = uma parte do caminho não é uma pasta
io-read-only = o sistema de arquivos é somente leitura
io-already-exists = já existe
io-invalid-name = não é um nome de arquivo
write-error = não foi possível escrever { $path }: { $what }: { $reason }; { $kept }
write-step-write = escrever
write-step-close = fechar
write-step-sync = sincronizar com o disco
write-step-create = criar
write-step-rename = mudar o nome
write-step-name = nome
write-step-create-folder = criar a pasta
set-folder-is-a-file = é um arquivo, não uma pasta: o phonglab grava um conjunto de arquivos em uma pasta; informe uma pasta, ou o nome de uma pasta nova
folder-link-dangling = é um link cujo destino não existe, e o phonglab não cria pastas por meio de um link
write-step-create-file-in = criar um arquivo em
write-kept-file = o arquivo que estava lá (se havia) não mudou
write-kept-nothing = nada foi escrito
write-not-a-regular-file = não é um arquivo comum (um link, uma pasta, um dispositivo ou um pipe): o phonglab só escreve em um arquivo comum ou em um novo
read-cannot = não foi possível ler { $path }: { $reason }
read-not-a-file = { $path } não é um arquivo comum
read-device-name = { $path } é um nome que o Windows reserva para um dispositivo (CON, PRN, AUX, NUL, COM1…, LPT1…), não um arquivo: o phonglab não lê dispositivos; indique o nome do próprio arquivo
read-too-large = { $path } tem { $size }; o phonglab lê { $what } de no máximo { $cap }
read-not-utf8 = { $path } não é texto UTF-8 (byte { $byte })
read-link-refused = { $path } é um link simbólico: não foi lido (o trabalho de um aluno só é lido de um arquivo, nunca por meio de um link)
file-kind-scenes = arquivos de cena
file-kind-code = notebooks e programas
err-output-is-input = { $output } é { $what } { $input }, que este comando lê (o mesmo arquivo): escrevê-lo destruiria o que é lido; escolha outra saída
err-output-is-other-output = { $output } é a outra saída { $other } (o mesmo arquivo): uma seria escrita por cima da outra; escolha dois arquivos diferentes
err-name-windows-device = { $name } é um nome que o Windows reserva para um dispositivo; escolha outro
err-name-windows-char = { $name } contém “{ $char }”, que o Windows não permite em um nome de arquivo (um “:” grava um fluxo oculto de outro arquivo); escolha um nome sem ele
err-name-windows-quote = { $name } contém “"”, que o Windows não permite em um nome de arquivo. No cmd, uma barra invertida logo antes das aspas finais mantém as aspas e junta ao nome o que vem depois: escreva a pasta sem a última barra ("C:\Exercícios de CG", e não "C:\Exercícios de CG\")
err-name-windows-end = o Windows remove o ponto ou o espaço no final de um nome ({ $name } seria { $kept }, outro arquivo); escolha um nome sem ele
input-kind-input = a entrada
input-kind-scene = a cena
input-kind-mesh = a malha
input-kind-code = o notebook ou programa
input-kind-cases = o arquivo de casos
# fix57c
check-verdict-too-few-digits = dígitos de menos para decidir (impresso com { $decimals ->
        [0] 0 casas decimais
        [one] 1 casa decimal
       *[other] { $decimals } casas decimais
    }, que não distinguem o gabarito do valor de um erro ou de 0: imprima mais, por exemplo np.set_printoptions(precision=8))
check-too-few-digits = não verificado por inteiro: dígitos de menos para distinguir o gabarito do valor de um erro ou de 0 ({ $names }; { $decimals ->
        [0] 0 casas decimais
        [one] 1 casa decimal
       *[other] { $decimals } casas decimais
    }). Imprima mais dígitos (np.set_printoptions(precision=8) no início, ou o padrão do NumPy), execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel) e verifique de novo
check-stale-count = não verificado por inteiro: o número de execução de uma célula não é o de uma execução ([{ $count }]: o Jupyter numera as células que executa 1, 2, 3, em ordem), então nada diz que as saídas são de uma única execução, em ordem. Execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel), salve e verifique de novo
check-stale-not-run = não verificado por inteiro: uma célula de código entre as numeradas [{ $above }] e [{ $below }] não tem número de execução (não foi executada nessa execução, ou suas saídas foram apagadas), então as saídas abaixo dela não são do seu código executado em ordem. Execute de novo todas as células (Jupyter: Restart & Run All, no menu Kernel), salve e verifique de novo
