"""Every translated term against the course vocabulary, typed here from the textbooks' words
(issue 9 §4): domain.md §9 for the headings (план брзина, план скоростей, план на скоростите,
načrt hitrosti, …) and the standard terms of the Serbian, Russian, Bulgarian and Slovenian
kinematics courses for the rest.  A term replaced by another language's word, or by a wrong
word, fails here; where courses use two words for one thing, both are listed.
"""

import pytest

from plans.i18n import LANGUAGES, TERMS, term

# key: {lang: words or (accepted variants)}; sr is Cyrillic (ijekavian/ekavian: ekavian)
VOCABULARY = {
    "mechanism": {"sr": "Кинематска шема", "ru": "План механизма", "bg": "План на механизма", "sl": "Kinematska shema"},
    "velocity_plan": {"sr": "План брзина", "ru": "План скоростей", "bg": "План на скоростите", "sl": "Načrt hitrosti"},
    "acceleration_plan": {"sr": "План убрзања", "ru": "План ускорений", "bg": "План на ускоренията", "sl": "Načrt pospeškov"},
    "positions_plan": {"sr": "План положаја механизма и путање тачака", "ru": "План положений механизма и траектории точек",
                       "bg": "План на положенията на механизма и траектории на точките", "sl": "Lege mehanizma in tirnice točk"},
    "scale_factor": {"sr": "размера", "ru": "масштаб", "bg": "мащаб", "sl": "merilo"},
    "scale_factors": {"sr": "Размере", "ru": "Масштабы", "bg": "Мащаби", "sl": "Merila"},
    "assur_group": {"sr": "Асурова група", "ru": "группа Ассура", "bg": "Асурова група", "sl": "Assurjeva skupina"},
    "structural_formula": {"sr": "Структурна формула", "ru": "Структурная формула", "bg": "Структурна формула", "sl": "Strukturna formula"},
    "vector_equations": {"sr": "Векторске једначине планова", "ru": "Векторные уравнения планов",
                         "bg": "Векторни уравнения на плановете", "sl": "Vektorske enačbe načrtov"},
    "loop_equations": {"sr": "Аналитичка провера: метода комплексног броја (једначине контура)",
                       "ru": "Аналитическая проверка: метод комплексных чисел (уравнения контуров)",
                       "bg": "Аналитична проверка: метод на комплексните числа (уравнения на контурите)",
                       "sl": "Analitična kontrola: metoda kompleksnih števil (enačbe zank)"},
    "results": {"sr": "Графички и аналитички резултати", "ru": "Графические и аналитические результаты",
                "bg": "Графични и аналитични резултати", "sl": "Grafični in analitični rezultati"},
    "quantity": {"sr": "величина", "ru": "величина", "bg": "величина", "sl": "količina"},
    "graphical": {"sr": "графички", "ru": "графически", "bg": "графично", "sl": "grafično"},
    "analytic": {"sr": "аналитички", "ru": "аналитически", "bg": "аналитично", "sl": "analitično"},
    "rel_error": {"sr": "рел. грешка", "ru": "отн. погр.", "bg": "отн. грешка", "sl": "rel. napaka"},
    "link": {"sr": "члан", "ru": "звено", "bg": "звено", "sl": "člen"},
    "slider": {"sr": "клизач", "ru": "ползун", "bg": "плъзгач", "sl": "drsnik"},
    "point": {"sr": "тачка", "ru": "точка", "bg": "точка", "sl": "točka"},
    "data": {"sr": "Подаци", "ru": "Исходные данные", "bg": "Изходни данни", "sl": "Podatki"},
    "driver": {"sr": "погонски члан", "ru": "ведущее звено", "bg": "водещо звено", "sl": "pogonski člen"},
    "position": {"sr": "Положај", "ru": "Положение", "bg": "Положение", "sl": "Lega"},
    "positions": {"sr": "положаја", "ru": "положений", "bg": "положения", "sl": "leg"},
    "positions_list": {"sr": "Положаји", "ru": "Положения", "bg": "Положения", "sl": "Lege"},
    "lengths": {"sr": "дужине", "ru": "длины", "bg": "дължини", "sl": "dolžine"},
    "fixed_points": {"sr": "непокретне тачке", "ru": "неподвижные точки", "bg": "неподвижни точки", "sl": "nepomične točke"},
    "absolute_velocity": {"sr": "апсолутна брзина", "ru": "абсолютная скорость", "bg": "абсолютна скорост", "sl": "absolutna hitrost"},
    "relative_velocity": {"sr": "релативна брзина", "ru": "относительная скорость", "bg": "относителна скорост", "sl": "relativna hitrost"},
    "absolute_acceleration": {"sr": "апсолутно убрзање", "ru": "абсолютное ускорение", "bg": "абсолютно ускорение", "sl": "absolutni pospešek"},
    "relative_acceleration": {"sr": "релативно убрзање aʳ", "ru": "относительное ускорение aʳ", "bg": "относително ускорение aʳ",
                              "sl": "relativni pospešek aʳ"},
    "normal_component": {"sr": "нормална компонента aⁿ", "ru": "нормальная составляющая aⁿ", "bg": "нормална съставяща aⁿ",
                         "sl": "normalna komponenta aⁿ"},
    "tangential_component": {"sr": "тангенцијална компонента aᵗ", "ru": "касательная составляющая aᵗ",
                             "bg": "тангенциална съставяща aᵗ", "sl": "tangencialna komponenta aᵗ"},
    "coriolis_component": {"sr": "Кориолисово убрзање aᵏ", "ru": "ускорение Кориолиса aᵏ", "bg": "Кориолисово ускорение aᵏ",
                           "sl": "Coriolisov pospešek aᵏ"},
    "construction_line": {"sr": "помоћна линија", "ru": "линия построения", "bg": "построителна линия", "sl": "konstrukcijska črta"},
    "path": {"sr": "путања тачке", "ru": "траектория точки", "bg": "траектория на точка", "sl": "tirnica točke"},
    "cycle_diagrams": {"sr": "Кинематски дијаграми током циклуса", "ru": "Кинематические диаграммы за цикл",
                       "bg": "Кинематични диаграми за един цикъл", "sl": "Kinematični diagrami v enem ciklu"},
    "angle": {"sr": "угао", "ru": "угол", "bg": "ъгъл", "sl": "kot"},
    "angular_velocity": {"sr": "угаона брзина", "ru": "угловая скорость", "bg": "ъглова скорост", "sl": "kotna hitrost"},
    "angular_acceleration": {"sr": "угаоно убрзање", "ru": "угловое ускорение", "bg": "ъглово ускорение", "sl": "kotni pospešek"},
    "velocity": {"sr": "брзина", "ru": "скорость", "bg": "скорост", "sl": "hitrost"},
    "acceleration": {"sr": "убрзање", "ru": "ускорение", "bg": "ускорение", "sl": "pospešek"},
    "links_motion": {"sr": "Чланови: угао, угаона брзина, угаоно убрзање", "ru": "Звенья: угол, угловая скорость, угловое ускорение",
                     "bg": "Звена: ъгъл, ъглова скорост, ъглово ускорение", "sl": "Členi: kot, kotna hitrost, kotni pospešek"},
    "points_motion": {"sr": "Тачке: брзина и убрзање", "ru": "Точки: скорость и ускорение", "bg": "Точки: скорост и ускорение",
                      "sl": "Točke: hitrost in pospešek"},
    "sliders_motion": {"sr": "Клизни парови: пут, релативна брзина, релативно и Кориолисово убрзање",
                       "ru": "Поступательные пары: перемещение, относительная скорость, относительное ускорение и ускорение Кориолиса",
                       "bg": "Транслационни двоици: преместване, относителна скорост, относително и Кориолисово ускорение",
                       "sl": "Drsni pari: pomik, relativna hitrost, relativni in Coriolisov pospešek"},
    "travel": {"sr": "пут", "ru": "перемещение", "bg": "преместване", "sl": "pomik"},
    "relative_velocity_short": {"sr": "релативна брзина", "ru": "относ. скорость", "bg": "относ. скорост", "sl": "relativna hitrost"},
    "relative_acceleration_short": {"sr": "релативно убрзање", "ru": "относ. ускорение", "bg": "относ. ускорение", "sl": "relativni pospešek"},
    "coriolis_acceleration": {"sr": "Кориолисово убрзање", "ru": "ускорение Кориолиса", "bg": "Кориолисово ускорение", "sl": "Coriolisov pospešek"},
    "turned_from_0": {"sr": "угао заокретања погонског члана од положаја 0", "ru": "угол поворота кривошипа от положения 0",
                      "bg": "ъгъл на завъртане на манивелата от положение 0", "sl": "zasuk ročice od lege 0"},
    "driver_position": {"sr": "положај погонског члана", "ru": "положение ведущего звена", "bg": "положение на водещото звено",
                        "sl": "lega pogonskega člena"},
    "no_assembly": {"sr": "механизам се не може саставити", "ru": "механизм не собирается", "bg": "механизмът не може да се сглоби",
                    "sl": "mehanizma ni mogoče sestaviti"},
    "near_dead_centre": {"sr": "близу мртвог положаја", "ru": "вблизи мёртвого положения", "bg": "близо до мъртво положение",
                         "sl": "blizu mrtve lege"},
    "dead_centre": {"sr": "у мртвом положају", "ru": "в мёртвом положении", "bg": "в мъртво положение", "sl": "v mrtvi legi"},
    "clipped": {"sr": "ван осе, близу мртвог положаја", "ru": "за пределами оси, вблизи мёртвого положения",
                "bg": "извън оста, близо до мъртво положение", "sl": "zunaj osi, blizu mrtve lege"},
    "not_drawn": {"sr": "нису нацртани", "ru": "не построены", "bg": "не са построени", "sl": "niso narisane"},
    "constant": {"sr": "исто у сваком положају", "ru": "одинаково во всех положениях", "bg": "еднакво във всички положения",
                 "sl": "enako v vseh legah"},
    "scales_per_position": {"sr": "$k_l$ исти за све положаје; $k_v$, $k_a$ изабрани за сваки положај",
                            "ru": "$k_l$ одинаков для всех положений; $k_v$, $k_a$ выбраны для каждого положения",
                            "bg": "$k_l$ еднакъв за всички положения; $k_v$, $k_a$ избрани за всяко положение",
                            "sl": "$k_l$ enak za vse lege; $k_v$, $k_a$ izbrana za vsako lego"},
    "sheet_positions": {"sr": "нацртани положаји", "ru": "построенные положения", "bg": "построени положения", "sl": "narisane lege"},
    "components": {"sr": "компоненте", "ru": "составляющие", "bg": "съставящи", "sl": "komponente"},
    "not_solved": {"sr": "није решено у овом положају", "ru": "в этом положении решения нет", "bg": "в това положение няма решение",
                   "sl": "v tej legi ni rešitve"},
    "continued": {"sr": "(наставак)", "ru": "(продолжение)", "bg": "(продължение)", "sl": "(nadaljevanje)"},
    "page": {"sr": "страна", "ru": "стр.", "bg": "стр.", "sl": "stran"},
    "contents": {"sr": "Садржај", "ru": "Содержание", "bg": "Съдържание", "sl": "Vsebina"},
    # instant centres: тренутни пол (брзина) / мгновенный центр скоростей / моментен център на скоростите / trenutni pol;
    # Kennedy's theorem: Кенедијева теорема / теорема Кеннеди (о трёх центрах) / теорема на Кенеди / Kennedyjev izrek;
    # circle diagram: кружни дијаграм / круговая диаграмма / кръгова диаграма / krožni diagram
    "instant_centres": {"sr": "Тренутни полови брзина", "ru": "Мгновенные центры скоростей", "bg": "Моментни центрове на скоростите", "sl": "Trenutni poli"},
    "centres_page": {"sr": "Тренутни полови брзина по Кенедијевој теореми: трећа метода за брзине", "ru": "Мгновенные центры скоростей по теореме Кеннеди: третий метод определения скоростей", "bg": "Моментни центрове на скоростите по теоремата на Кенеди: трети метод за скоростите", "sl": "Trenutni poli po Kennedyjevem izreku: tretja metoda za hitrosti"},
    "kennedy_theorem": {"sr": "Кенедијева теорема", "ru": "теорема Кеннеди (о трёх центрах)", "bg": "теорема на Кенеди", "sl": "Kennedyjev izrek"},
    "kennedy_statement": {"sr": "три тренутна пола било која три члана леже на једној правој", "ru": "три мгновенных центра скоростей любых трёх звеньев лежат на одной прямой", "bg": "трите моментни центъра на скоростите на всеки три звена лежат на една права", "sl": "trije trenutni poli poljubnih treh členov ležijo na isti premici"},
    "circle_diagram": {"sr": "кружни дијаграм", "ru": "круговая диаграмма", "bg": "кръгова диаграма", "sl": "krožni diagram"},
    "circle_diagram_legend": {"sr": "странице: полови у кинематичким паровима;\nиспрекидано: по Кенедијевој теореми", "ru": "стороны: центры в кинематических парах;\nштрихи: по теореме Кеннеди", "bg": "страни: центрове в кинематичните двоици;\nпрекъснато: по теоремата на Кенеди", "sl": "stranice: poli v kinematičnih parih;\nčrtkano: po Kennedyjevem izreku"},
    "centres_legend": {"sr": "кружићи: полови у кинематичким паровима; тачке: нађени по Кенедијевој теореми на испрекиданим правама", "ru": "кружки: центры в кинематических парах; точки: найдены по теореме Кеннеди на штриховых прямых", "bg": "кръгчета: центрове в кинематичните двоици; точки: намерени по теоремата на Кенеди върху прекъснатите прави", "sl": "krožci: poli v kinematičnih parih; pike: najdeni po Kennedyjevem izreku na črtkanih premicah"},
    "centres_edge_legend": {"sr": "стрелица на ивици показује удаљени пол (+ његово растојање иза стрелице) или пол у бесконачности (∞)", "ru": "стрелка у края указывает на далёкий центр (+ его расстояние за стрелкой) или на центр в бесконечности (∞)", "bg": "стрелка в края сочи към далечен център (+ разстоянието му след стрелката) или към център в безкрайността (∞)", "sl": "puščica na robu kaže na oddaljeni pol (+ njegova razdalja za puščico) ali na pol v neskončnosti (∞)"},
    "centre_undetermined": {"sr": "неодређен", "ru": "не определён", "bg": "неопределен", "sl": "nedoločen"},
    "centre_undetermined_why": {"sr": "његове Кенедијеве праве се у овом положају поклапају (брзине га не захтевају)", "ru": "его прямые Кеннеди в этом положении совпадают (для скоростей он не нужен)", "bg": "правите на Кенеди за него съвпадат в това положение (скоростите не се нуждаят от него)", "sl": "njegove Kennedyjeve premice v tej legi sovpadajo (hitrosti ga ne potrebujejo)"},
    "by_centres": {"sr": "тренутни полови", "ru": "мгн. центры", "bg": "моментни центрове", "sl": "trenutni poli"},
    "centres_results": {"sr": "Брзине из тренутних полова и аналитичке вредности", "ru": "Скорости по мгновенным центрам и аналитические значения", "bg": "Скорости от моментните центрове и аналитични стойности", "sl": "Hitrosti iz trenutnih polov in analitične vrednosti"},
    "centres_omega_rule": {"sr": "ω члана из ω погонског члана, преко полова", "ru": "ω звена по ω ведущего звена, через центры", "bg": "ω на звеното от ω на водещото звено, чрез центровете", "sl": "ω člena iz ω pogonskega člena, prek polov"},
    "centres_v_rule": {"sr": "брзина тачке из пола око ког се окреће њен члан", "ru": "скорость точки по центру, вокруг которого поворачивается её звено", "bg": "скорост на точка от центъра, около който се завърта звеното ѝ", "sl": "hitrost točke iz pola, okoli katerega se vrti njen člen"},
    # readings of a plan (issue 10 §2): the courses' words for a reading and a segment (the sense of rotation is
    # the arc arrow ↺/↻, no word)
    "readings": {"sr": "очитавања", "ru": "отсчёты", "bg": "отчитания", "sl": "odčitki"},
    "segment": {"sr": "дуж", "ru": "отрезок", "bg": "отсечка", "sl": "daljica"},
    # the cycle law, strokes and Grashof classes (issue 19): the course words for the motion of a mechanism
    "driver_law": {"sr": "закон кретања погонског члана", "ru": "закон движения ведущего звена",
                   "bg": "закон на движение на водещото звено", "sl": "zakon gibanja pogonskega člena"},
    "law_constant": {"sr": "константна брзина", "ru": "постоянная скорость", "bg": "постоянна скорост", "sl": "konstantna hitrost"},
    "law_uniform": {"sr": "равномерно убрзано", "ru": "равноускоренно", "bg": "равноускорително", "sl": "enakomerno pospešeno"},
    "law_harmonic": {"sr": "хармонијско љуљање између", "ru": "гармоническое качание между", "bg": "хармонично люлеене между",
                     "sl": "harmonično nihanje med"},
    "law_at": {"sr": "при", "ru": "при", "bg": "при", "sl": "pri"},
    "law_at_limits": {"sr": "у граничним положајима", "ru": "в крайних положениях", "bg": "в крайните положения", "sl": "v mejnih legah"},
    "output_link": {"sr": "излазни члан", "ru": "выходное звено", "bg": "изходно звено", "sl": "izhodni člen"},
    "stroke_H": {"sr": "ход", "ru": "ход", "bg": "ход", "sl": "hod"},
    "swing_psi": {"sr": "угао љуљања", "ru": "угол качания", "bg": "ъгъл на люлеене", "sl": "kot nihanja"},
    "extreme_positions": {"sr": "крајњи положаји", "ru": "крайние положения", "bg": "крайни положения", "sl": "skrajni legi"},
    "working_stroke": {"sr": "радни ход", "ru": "рабочий ход", "bg": "работен ход", "sl": "delovni hod"},
    "time": {"sr": "време", "ru": "время", "bg": "време", "sl": "čas"},
    "grashof_class": {"sr": "Грасхофова класа", "ru": "класс по Грасгофу", "bg": "клас по Грасхоф", "sl": "Grashofov razred"},
    "crank-rocker": {"sr": "кривајно-клацкајући", "ru": "кривошипно-коромысловый", "bg": "колянно-кобиличен", "sl": "ročično-nihajni"},
    "double-crank": {"sr": "двокривајни", "ru": "двухкривошипный", "bg": "двуколянов", "sl": "dvoročični"},
    "double-rocker": {"sr": "двоклацкајући", "ru": "двухкоромысловый", "bg": "двукобиличен", "sl": "dvonihajni"},
    "change point": {"sr": "гранични случај", "ru": "переходный случай", "bg": "граничен случай", "sl": "mejni primer"},
    "triple-rocker": {"sr": "троклацкајући (није Грасхофов)", "ru": "трёхкоромысловый (не Грасгофов)",
                      "bg": "трикобиличен (не е Грасхофов)", "sl": "trinihajni (ni Grashofov)"},
    "turn_fully": {"sr": "окрећу се пуним кругом", "ru": "проворачиваются полностью", "bg": "се завъртат изцяло", "sl": "se zavrtijo v celoti"},
    "none_turns": {"sr": "ниједан члан се не окреће пуним кругом", "ru": "ни одно звено не проворачивается",
                   "bg": "никое звено не се завърта изцяло", "sl": "noben člen se ne zavrti v celoti"},
    # kinematic diagrams of the output link by graphical differentiation (issue 19 §4): метод хорд / метода тетива /
    # метод на хордите / metoda tetiv; полюсное расстояние H; ползун / клизач / плъзгач / drsnik; коромысло / клацкач /
    # кобилица / nihalka; метод касательных / метода тангенти / метод на допирателните / metoda tangent
    "kinematic_diagrams": {"sr": "Кинематски дијаграми излазног члана", "ru": "Кинематические диаграммы выходного звена", "bg": "Кинематични диаграми на изходното звено", "sl": "Kinematični diagrami izhodnega člena"},
    "graphical_differentiation": {"sr": "графичко диференцирање методом тетива", "ru": "графическое дифференцирование методом хорд", "bg": "графично диференциране по метода на хордите", "sl": "grafično odvajanje z metodo tetiv"},
    "output_slider": {"sr": "излазни члан: клизач", "ru": "выходное звено: ползун", "bg": "изходно звено: плъзгач", "sl": "izhodni člen: drsnik"},
    "output_rocker": {"sr": "излазни члан: клацкач", "ru": "выходное звено: коромысло", "bg": "изходно звено: кобилица", "sl": "izhodni člen: nihalka"},
    "displacement": {"sr": "померање", "ru": "перемещение", "bg": "преместване", "sl": "pomik"},
    "cycle_time": {"sr": "време једног циклуса", "ru": "время одного цикла", "bg": "време на един цикъл", "sl": "čas enega cikla"},
    "abscissa_length": {"sr": "дужина апсцисе", "ru": "длина оси абсцисс", "bg": "дължина на абсцисата", "sl": "dolžina abscise"},
    "chord": {"sr": "тетива", "ru": "хорда", "bg": "хорда", "sl": "tetiva"},
    "ray": {"sr": "зрак из пола, паралелан тетиви", "ru": "луч из полюса, параллельный хорде", "bg": "лъч от полюса, успореден на хордата", "sl": "žarek iz pola, vzporeden s tetivo"},
    "chords_curve": {"sr": "крива кроз тачке", "ru": "кривая через точки", "bg": "крива през точките", "sl": "krivulja skozi točke"},
    "analytic_curve": {"sr": "аналитички, за поређење", "ru": "аналитически, для сравнения", "bg": "аналитично, за сравнение", "sl": "analitično, za primerjavo"},
    "diagrams_table": {"sr": "Излазни члан у сваком положају: из дијаграма, из планова и аналитички", "ru": "Выходное звено во всех положениях: по диаграммам, по планам и аналитически", "bg": "Изходното звено във всяко положение: от диаграмите, от плановете и аналитично", "sl": "Izhodni člen v vsaki legi: iz diagramov, iz načrtov in analitično"},
    "from_diagram": {"sr": "дијагр.", "ru": "диагр.", "bg": "диагр.", "sl": "diagr."},
    "from_plans": {"sr": "план", "ru": "план", "bg": "план", "sl": "načrt"},
    "from_analytic": {"sr": "аналит.", "ru": "аналит.", "bg": "аналит.", "sl": "analit."},
    "diagram_error_note": {"sr": "δ: грешка према аналитичкој вредности, у % њене највеће апсолутне вредности у положајима (у % саме вредности била би бесконачна где она пролази кроз нулу)", "ru": "δ: погрешность относительно аналитического значения, в % от его наибольшей величины по положениям (в % от самого значения она бесконечна там, где оно проходит через нуль)", "bg": "δ: грешка спрямо аналитичната стойност, в % от най-голямата ѝ големина в положенията (в % от самата стойност тя е безкрайна там, където стойността минава през нула)", "sl": "δ: napaka glede na analitično vrednost, v % njene največje absolutne vrednosti v legah (v % same vrednosti bi bila neskončna, kjer vrednost gre skozi nič)"},
    "method_of_tangents": {"sr": "метода тангенти", "ru": "метод касательных", "bg": "метод на допирателните", "sl": "metoda tangent"},
    "kd_no_output": {"sr": "механизам нема излазни клизач (на вођици постоља) ни клацкач (који се обрће око тачке постоља); наведите га са [output] link", "ru": "у механизма нет выходного ползуна (на направляющей стойки) или коромысла (вращающегося вокруг точки стойки); укажите его в [output] link", "bg": "механизмът няма изходен плъзгач (по водач на стойката) или кобилица (въртяща се около точка на стойката); посочете го с [output] link", "sl": "mehanizem nima izhodnega drsnika (na vodilu ogrodja) ali nihalke (ki se vrti okoli točke ogrodja); navedite ga z [output] link"},
    "kd_unsolved": {"sr": "механизам није решен у положајима {positions}: графичко диференцирање спаја суседне положаје и потребан му је сваки", "ru": "механизм не решается в положениях {positions}: графическое дифференцирование соединяет соседние положения, и нужны все", "bg": "механизмът не е решен в положенията {positions}: графичното диференциране свързва съседни положения и са нужни всички", "sl": "mehanizem ni rešen v legah {positions}: grafično odvajanje povezuje sosednje lege in potrebuje vse"},
    "kd_not_drawn": {"sr": "Дијаграми нису нацртани", "ru": "Диаграммы не построены", "bg": "Диаграмите не са построени", "sl": "Diagrami niso narisani"},
    "chords_order": {"sr": "грешка метода тетива опада као Δt²: са двоструко више положаја на око четвртину", "ru": "погрешность метода хорд убывает как Δt²: при вдвое большем числе положений примерно вчетверо", "bg": "грешката на метода на хордите намалява като Δt²: при двойно повече положения до около една четвърт", "sl": "napaka metode tetiv pada kot Δt²: pri dvakrat več legah na približno četrtino"},
    # --- forces --- (domain.md §11's table where it has the word)
    "kinetostatics": {"sr": "Кинетостатичка анализа", "ru": "Кинетостатический анализ", "bg": "Кинетостатичен анализ",
                      "sl": "Kinetostatična analiza"},
    "loads": {"sr": "Оптерећења", "ru": "Нагрузки", "bg": "Натоварвания", "sl": "Obremenitve"},
    "reactions": {"sr": "Реакције у кинематским паровима", "ru": "Реакции в кинематических парах",
                  "bg": "Реакции в кинематичните двойки", "sl": "Reakcije v kinematičnih parih"},
    "reaction_convention": {"sr": "R_ij: сила којом члан i делује на члан j (0: постоље)",
                            "ru": "R_ij: сила действия звена i на звено j (0: стойка)",
                            "bg": "R_ij: сила, с която звено i действа на звено j (0: стойка)",
                            "sl": "R_ij: sila, s katero člen i deluje na člen j (0: ogrodje)"},
    "balancing_moment": {"sr": "Уравнотежни момент", "ru": "Уравновешивающий момент", "bg": "Уравновесяващ момент",
                         "sl": "Uravnotežilni moment"},
    "balancing_force": {"sr": "Уравнотежна сила", "ru": "Уравновешивающая сила", "bg": "Уравновесяваща сила",
                        "sl": "Uravnotežilna sila"},
    "joukowski_lever": {"sr": "Жуковљева полуга", "ru": "Рычаг Жуковского", "bg": "Лост на Жуковски", "sl": "Žukovskijev vzvod"},
    "force_plans": {"sr": "планови сила", "ru": "планы сил", "bg": "планове на силите", "sl": "načrti sil"},
    "weight": {"sr": "тежина", "ru": "сила тяжести", "bg": "тегло", "sl": "teža"},
    "inertia_force": {"sr": "сила инерције", "ru": "сила инерции", "bg": "инерционна сила", "sl": "vztrajnostna sila"},
    "inertia_couple": {"sr": "момент сила инерције", "ru": "момент сил инерции", "bg": "момент на инерционните сили",
                       "sl": "moment vztrajnostnih sil"},
    "external_force": {"sr": "сила", "ru": "сила", "bg": "сила", "sl": "sila"},
    "resistance": {"sr": "сила отпора", "ru": "сила сопротивления", "bg": "съпротивителна сила", "sl": "sila upora"},
    "couple": {"sr": "спрег сила", "ru": "пара сил", "bg": "двоица сили", "sl": "dvojica sil"},
    "normal_force": {"sr": "нормална сила", "ru": "нормальная сила", "bg": "нормална сила", "sl": "normalna sila"},
    "point_of_action": {"sr": "нападна тачка", "ru": "точка приложения", "bg": "приложна точка", "sl": "prijemališče"},
    "kind": {"sr": "врста", "ru": "вид", "bg": "вид", "sl": "vrsta"},
    "power_balance": {"sr": "Биланс снага", "ru": "Баланс мощностей", "bg": "Баланс на мощностите", "sl": "Bilanca moči"},
    "residual": {"sr": "остатак", "ru": "невязка", "bg": "остатък", "sl": "ostanek"},
    "ccw_positive": {"sr": "позитиван супротно кретању казаљке на сату", "ru": "положителен против часовой стрелки",
                     "bg": "положителен обратно на часовниковата стрелка", "sl": "pozitiven v nasprotni smeri urinega kazalca"},
    "along_guide": {"sr": "дуж вођице погонског члана", "ru": "вдоль направляющей ведущего звена",
                    "bg": "по направляващата на водещото звено", "sl": "vzdolž vodila pogonskega člena"},
    "lever_left_out": {"sr": "Жуковљева полуга изостављена: погонски члан мирује",
                       "ru": "Рычаг Жуковского не построен: ведущее звено неподвижно",
                       "bg": "Лостът на Жуковски е пропуснат: водещото звено е неподвижно",
                       "sl": "Žukovskijev vzvod izpuščen: pogonski člen miruje"},
    # the plate (issue 20): title block (штамп: разработал, проверил, лист, листов), the plans of every position, the
    # known parts marked, the working and idle (холостой / повратни / празен / povratni) stroke, the assembly in words
    "plate_title": {"sr": "Кинематичка анализа механизма", "ru": "Кинематический анализ механизма", "bg": "Кинематичен анализ на механизма", "sl": "Kinematična analiza mehanizma"},
    "drawn_by": {"sr": "Цртао", "ru": "Разработал", "bg": "Изработил", "sl": "Risal"},
    "checked_by": {"sr": "Прегледао", "ru": "Проверил", "bg": "Проверил", "sl": "Pregledal"},
    "date": {"sr": "Датум", "ru": "Дата", "bg": "Дата", "sl": "Datum"},
    "sheet": {"sr": "Лист", "ru": "Лист", "bg": "Лист", "sl": "List"},
    "of_sheets": {"sr": "од", "ru": "из", "bg": "от", "sl": "od"},
    "underlines": {"sr": "подвучено једном: познат правац; двапут: познати интензитет и правац", "ru": "подчёркнуто один раз — известно направление; дважды — известны величина и направление", "bg": "подчертано веднъж — известна посока; два пъти — известни големина и посока", "sl": "podčrtano enkrat: znana smer; dvakrat: znani velikost in smer"},
    "velocity_plans": {"sr": "Планови брзина", "ru": "Планы скоростей", "bg": "Планове на скоростите", "sl": "Načrti hitrosti"},
    "acceleration_plans": {"sr": "Планови убрзања", "ru": "Планы ускорений", "bg": "Планове на ускоренията", "sl": "Načrti pospeškov"},
    "each_from_its_pole": {"sr": "сваки из свог пола", "ru": "каждый из своего полюса", "bg": "всеки от своя полюс", "sl": "vsak iz svojega pola"},
    "scales_each_position": {"sr": "размере изабране за сваки положај", "ru": "масштабы выбраны для каждого положения", "bg": "мащабите са избрани за всяко положение", "sl": "merila izbrana za vsako lego"},
    "idle_stroke": {"sr": "повратни ход", "ru": "холостой ход", "bg": "празен ход", "sl": "povratni hod"},
    "assembly": {"sr": "Склоп група", "ru": "Сборка групп", "bg": "Сглобяване на групите", "sl": "Sestav skupin"},
    "group": {"sr": "група", "ru": "группа", "bg": "група", "sl": "skupina"},
    "assembly_side": {"sr": "{c} {side} од праве {b}{d}, гледано од {b} ка {d}", "ru": "{c} {side} от прямой {b}{d}, если смотреть от {b} к {d}", "bg": "{c} {side} от правата {b}{d}, гледано от {b} към {d}", "sl": "{c} {side} od premice {b}{d}, gledano od {b} proti {d}"},
    "left": {"sr": "лево", "ru": "слева", "bg": "вляво", "sl": "levo"},
    "right": {"sr": "десно", "ru": "справа", "bg": "вдясно", "sl": "desno"},
    "assembly_slider_side": {"sr": "клизач {c} {where} {b}", "ru": "ползун {c} {where} {b}", "bg": "плъзгач {c} {where} {b}", "sl": "drsnik {c} {where} {b}"},
    "right_of": {"sr": "десно од", "ru": "справа от", "bg": "вдясно от", "sl": "desno od"},
    "left_of": {"sr": "лево од", "ru": "слева от", "bg": "вляво от", "sl": "levo od"},
    "above": {"sr": "изнад", "ru": "выше", "bg": "над", "sl": "nad"},
    "below": {"sr": "испод", "ru": "ниже", "bg": "под", "sl": "pod"},
    "assembly_along": {"sr": "клизач {c} {where} {b} дуж вођице {key}", "ru": "ползун {c} {where} {b} вдоль направляющей {key}", "bg": "плъзгач {c} {where} {b} по водача {key}", "sl": "drsnik {c} {where} {b} vzdolž vodila {key}"},
    "ahead_of": {"sr": "испред", "ru": "впереди", "bg": "пред", "sl": "pred"},
    "behind": {"sr": "иза", "ru": "позади", "bg": "зад", "sl": "za"},
    "assembly_directed": {"sr": "{key} усмерена од {a} ка {b}", "ru": "{key} направлена от {a} к {b}", "bg": "{key} е насочен от {a} към {b}", "sl": "{key} usmerjen od {a} proti {b}"},
    "open_four_bar": {"sr": "отворени зглавкасти четвороугао", "ru": "открытый шарнирный четырёхзвенник", "bg": "отворен шарнирен четиризвенник", "sl": "odprti štirizgibni mehanizem"},
    "crossed_four_bar": {"sr": "укрштени зглавкасти четвороугао", "ru": "перекрещенный шарнирный четырёхзвенник", "bg": "кръстосан шарнирен четиризвенник", "sl": "prekrižani štirizgibni mehanizem"},
    "comparison": {"sr": "Графичке и аналитичке вредности", "ru": "Графические и аналитические значения", "bg": "Графични и аналитични стойности", "sl": "Grafične in analitične vrednosti"},
}

#: domain.md §9, word for word: the headings every handout carries.
DOMAIN_MD = {
    "velocity_plan": {"sr": "план брзина", "ru": "план скоростей", "bg": "план на скоростите", "sl": "načrt hitrosti"},
    "acceleration_plan": {"sr": "план убрзања", "ru": "план ускорений", "bg": "план на ускоренията", "sl": "načrt pospeškov"},
    "scale_factor": {"sr": "размера", "ru": "масштаб", "sl": "merilo"},
    "assur_group": {"sr": "асурова група", "ru": "группа ассура", "bg": "асурова група", "sl": "assurjeva skupina"},
    "coriolis_acceleration": {"sr": "кориолисово убрзање", "ru": "ускорение кориолиса", "sl": "coriolisov pospešek"},
    "mechanism": {"sr": "кинематска шема", "ru": "план механизма", "sl": "kinematska shema"},
}


def test_the_vocabulary_covers_every_key():
    assert set(VOCABULARY) == set(TERMS)


@pytest.mark.parametrize("key", sorted(VOCABULARY))
@pytest.mark.parametrize("lang", [lang for lang in LANGUAGES if lang != "en"])
def test_every_term_is_the_course_word(key, lang):
    expected = VOCABULARY[key][lang]
    accepted = expected if isinstance(expected, tuple) else (expected,)
    assert term(key, lang) in accepted


@pytest.mark.parametrize("key", sorted(DOMAIN_MD))
def test_the_headings_are_the_words_of_domain_md(key):
    for lang, words in DOMAIN_MD[key].items():
        assert term(key, lang).lower().replace("ё", "е") == words, (key, lang)


def test_no_term_is_another_languages_word():
    # a Bulgarian heading replaced by the Russian one (or the Slovenian by the Serbian Latin
    # transliteration) would still be Cyrillic (or Latin): check the words differ where the languages do
    for key in ("velocity_plan", "acceleration_plan", "mechanism", "scale_factor", "slider", "angle", "velocity"):
        assert term(key, "ru") != term(key, "bg"), key
        assert term(key, "sr") != term(key, "ru"), key
