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
    "centres_edge_legend": {"sr": "стрелица на ивици показује пол ван цртежа: његово растојање иза врха стрелице у mm цртежа (× kₗ = метри), или ∞ у бесконачности", "ru": "стрелка у края указывает на центр за пределами чертежа: его расстояние за остриём стрелки в мм чертежа (× kₗ = метры), или ∞ в бесконечности", "bg": "стрелка в края сочи към център извън чертежа: разстоянието му след върха на стрелката в mm от чертежа (× kₗ = метри), или ∞ в безкрайността", "sl": "puščica na robu kaže na pol zunaj risbe: njegova razdalja za konico puščice v mm risbe (× kₗ = metri), ali ∞ v neskončnosti"},
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
