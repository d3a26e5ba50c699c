"""Headings and legend words in the languages the method is taught in, in one place.

English is the default; Serbian (Cyrillic), Russian, Bulgarian and Slovenian
use the terms of the textbooks (domain.md §8) where they name the thing:
план брзина / план скоростей / план на скоростите / načrt hitrosti, and so on.
Point letters and symbols (v_B, a^k, ω₃, k_v) are never translated.

>>> term("velocity_plan", "ru")
'План скоростей'
>>> term("velocity_plan", "sl")
'Načrt hitrosti'
"""

from __future__ import annotations

import re

__all__ = ["LANGUAGES", "TERMS", "term", "check_language", "reason_text", "branch_text"]

#: language code -> its name in that language
LANGUAGES = {
    "en": "English",
    "sr": "Српски",
    "ru": "Русский",
    "bg": "Български",
    "sl": "Slovenščina",
}

#: key -> language -> words.  Keep every key complete in every language.
TERMS: dict[str, dict[str, str]] = {
    # --- drawings -------------------------------------------------------------
    "mechanism": {
        "en": "Mechanism",
        "sr": "Кинематска шема",
        "ru": "План механизма",
        "bg": "План на механизма",
        "sl": "Kinematska shema",
    },
    "velocity_plan": {
        "en": "Velocity plan",
        "sr": "План брзина",
        "ru": "План скоростей",
        "bg": "План на скоростите",
        "sl": "Načrt hitrosti",
    },
    "acceleration_plan": {
        "en": "Acceleration plan",
        "sr": "План убрзања",
        "ru": "План ускорений",
        "bg": "План на ускоренията",
        "sl": "Načrt pospeškov",
    },
    "positions_plan": {
        "en": "Mechanism in its positions, with the paths of its points",
        "sr": "План положаја механизма и путање тачака",
        "ru": "План положений механизма и траектории точек",
        "bg": "План на положенията на механизма и траектории на точките",
        "sl": "Lege mehanizma in tirnice točk",
    },
    "scale_factor": {
        "en": "scale factor",
        "sr": "размера",
        "ru": "масштаб",
        "bg": "мащаб",
        "sl": "merilo",
    },
    "scale_factors": {
        "en": "Scale factors",
        "sr": "Размере",
        "ru": "Масштабы",
        "bg": "Мащаби",
        "sl": "Merila",
    },
    "assur_group": {
        "en": "Assur group",
        "sr": "Асурова група",
        "ru": "группа Ассура",
        "bg": "Асурова група",
        "sl": "Assurjeva skupina",
    },
    "structural_formula": {
        "en": "Structural formula",
        "sr": "Структурна формула",
        "ru": "Структурная формула",
        "bg": "Структурна формула",
        "sl": "Strukturna formula",
    },
    "vector_equations": {
        "en": "Vector equations",
        "sr": "Векторске једначине планова",
        "ru": "Векторные уравнения планов",
        "bg": "Векторни уравнения на плановете",
        "sl": "Vektorske enačbe načrtov",
    },
    "loop_equations": {
        "en": "Analytic check: complex-number method (loop equations)",
        "sr": "Аналитичка провера: метода комплексних бројева (једначине контура)",
        "ru": "Аналитическая проверка: метод комплексных чисел (уравнения контуров)",
        "bg": "Аналитична проверка: метод на комплексните числа (уравнения на контурите)",
        "sl": "Analitična kontrola: metoda kompleksnih števil (enačbe zank)",
    },
    "results": {
        "en": "Graphical against analytic",
        "sr": "Графички и аналитички резултати",
        "ru": "Графические и аналитические результаты",
        "bg": "Графични и аналитични резултати",
        "sl": "Grafični in analitični rezultati",
    },
    "quantity": {"en": "quantity", "sr": "величина", "ru": "величина", "bg": "величина", "sl": "količina"},
    "graphical": {"en": "graphical", "sr": "графички", "ru": "графически", "bg": "графично", "sl": "grafično"},
    "analytic": {"en": "analytic", "sr": "аналитички", "ru": "аналитически", "bg": "аналитично", "sl": "analitično"},
    # a comparison table's column of the plans' values: the course's "по плану" (from the plan), not an adverb
    "by_plan": {"en": "from the plan", "sr": "са плана", "ru": "по плану", "bg": "от плана", "sl": "iz načrta"},
    # the readings table's last column: the value the segment × the scale factor gives
    "reading_value": {"en": "value", "sr": "вредност", "ru": "значение", "bg": "стойност", "sl": "vrednost"},
    "rel_error": {"en": "rel. error", "sr": "рел. грешка", "ru": "отн. погр.", "bg": "отн. грешка", "sl": "rel. napaka"},
    "link": {"en": "link", "sr": "члан", "ru": "звено", "bg": "звено", "sl": "člen"},
    "slider": {"en": "slider", "sr": "клизач", "ru": "ползун", "bg": "плъзгач", "sl": "drsnik"},
    "point": {"en": "point", "sr": "тачка", "ru": "точка", "bg": "точка", "sl": "točka"},
    "data": {"en": "Data", "sr": "Подаци", "ru": "Исходные данные", "bg": "Изходни данни", "sl": "Podatki"},
    "driver": {"en": "driver", "sr": "погонски члан", "ru": "ведущее звено", "bg": "водещо звено", "sl": "pogonski člen"},
    "position": {"en": "Position", "sr": "Положај", "ru": "Положение", "bg": "Положение", "sl": "Lega"},
    "positions": {"en": "positions", "sr": "положаја", "ru": "положений", "bg": "положения", "sl": "leg"},
    "positions_list": {"en": "Positions", "sr": "Положаји", "ru": "Положения", "bg": "Положения", "sl": "Lege"},
    "lengths": {"en": "lengths", "sr": "дужине", "ru": "длины", "bg": "дължини", "sl": "dolžine"},
    # a guide line's angle in the given data: "втулка под ъгъл 60°" (the name as the scene gives it)
    "line_at": {"en": "{name} at {angle}°", "sr": "{name} под углом {angle}°", "ru": "{name} под углом {angle}°",
                "bg": "{name} под ъгъл {angle}°", "sl": "{name} pod kotom {angle}°"},
    "from_point": {"en": "from", "sr": "од", "ru": "от", "bg": "от", "sl": "od"},  # a guide's offset e from the crank's pivot
    "fixed_points": {"en": "fixed points", "sr": "непокретне тачке", "ru": "неподвижные точки", "bg": "неподвижни точки", "sl": "nepomične točke"},
    # --- plan legends ---------------------------------------------------------------
    "absolute_velocity": {
        "en": "absolute velocity",
        "sr": "апсолутна брзина",
        "ru": "абсолютная скорость",
        "bg": "абсолютна скорост",
        "sl": "absolutna hitrost",
    },
    "relative_velocity": {
        "en": "relative velocity",
        "sr": "релативна брзина",
        "ru": "относительная скорость",
        "bg": "относителна скорост",
        "sl": "relativna hitrost",
    },
    "absolute_acceleration": {
        "en": "absolute acceleration",
        "sr": "апсолутно убрзање",
        "ru": "абсолютное ускорение",
        "bg": "абсолютно ускорение",
        "sl": "absolutni pospešek",
    },
    "relative_acceleration": {
        "en": "relative (sliding) acceleration aʳ",
        "sr": "релативно убрзање aʳ",
        "ru": "относительное ускорение aʳ",
        "bg": "относително ускорение aʳ",
        "sl": "relativni pospešek aʳ",
    },
    "normal_component": {
        "en": "normal component aⁿ",
        "sr": "нормална компонента aⁿ",
        "ru": "нормальная составляющая aⁿ",
        "bg": "нормална съставяща aⁿ",
        "sl": "normalna komponenta aⁿ",
    },
    "tangential_component": {
        "en": "tangential component aᵗ",
        "sr": "тангенцијална компонента aᵗ",
        "ru": "касательная составляющая aᵗ",
        "bg": "тангенциална съставяща aᵗ",
        "sl": "tangencialna komponenta aᵗ",
    },
    "coriolis_component": {
        "en": "Coriolis component aᵏ",
        "sr": "Кориолисово убрзање aᵏ",
        "ru": "ускорение Кориолиса aᵏ",
        "bg": "Кориолисово ускорение aᵏ",
        "sl": "Coriolisov pospešek aᵏ",
    },
    "link_image": {"en": "image of a link", "sr": "слика члана", "ru": "образ звена", "bg": "образ на звено", "sl": "slika člena"},
    "construction_line": {
        "en": "construction line",
        "sr": "помоћна линија",
        "ru": "линия построения",
        "bg": "построителна линия",
        "sl": "konstrukcijska črta",
    },
    "path": {"en": "path of point", "sr": "путања тачке", "ru": "траектория точки", "bg": "траектория на точка", "sl": "tirnica točke"},
    # --- cycle diagrams -------------------------------------------------------------
    "cycle_diagrams": {
        "en": "Kinematic diagrams over the cycle",
        "sr": "Кинематски дијаграми током циклуса",
        "ru": "Кинематические диаграммы за цикл",
        "bg": "Кинематични диаграми за един цикъл",
        "sl": "Kinematični diagrami v enem ciklu",
    },
    "angle": {"en": "angle", "sr": "угао", "ru": "угол", "bg": "ъгъл", "sl": "kot"},
    "angular_velocity": {"en": "angular velocity", "sr": "угаона брзина", "ru": "угловая скорость", "bg": "ъглова скорост", "sl": "kotna hitrost"},
    "angular_acceleration": {"en": "angular acceleration", "sr": "угаоно убрзање", "ru": "угловое ускорение", "bg": "ъглово ускорение", "sl": "kotni pospešek"},
    "velocity": {"en": "velocity", "sr": "брзина", "ru": "скорость", "bg": "скорост", "sl": "hitrost"},
    "acceleration": {"en": "acceleration", "sr": "убрзање", "ru": "ускорение", "bg": "ускорение", "sl": "pospešek"},
    "links_motion": {
        "en": "Links: angle, angular velocity, angular acceleration",
        "sr": "Чланови: угао, угаона брзина, угаоно убрзање",
        "ru": "Звенья: угол, угловая скорость, угловое ускорение",
        "bg": "Звена: ъгъл, ъглова скорост, ъглово ускорение",
        "sl": "Členi: kot, kotna hitrost, kotni pospešek",
    },
    "points_motion": {
        "en": "Points: velocity and acceleration",
        "sr": "Тачке: брзина и убрзање",
        "ru": "Точки: скорость и ускорение",
        "bg": "Точки: скорост и ускорение",
        "sl": "Točke: hitrost in pospešek",
    },
    "sliders_motion_relative": {
        "en": "Prismatic pairs: position on the guide, relative velocity and acceleration",
        "sr": "Клизни парови: положај на вођици, релативна брзина и убрзање",
        "ru": "Поступательные пары: положение на направляющей, относительная скорость и ускорение",
        "bg": "Транслационни двойки: положение по водача, относителна скорост и ускорение",
        "sl": "Drsni pari: lega na vodilu, relativna hitrost in pospešek",
    },
    "sliders_motion": {
        "en": "Prismatic pairs: position on the guide, relative velocity, relative and Coriolis accelerations",
        "sr": "Клизни парови: положај на вођици, релативна брзина, релативно и Кориолисово убрзање",
        "ru": "Поступательные пары: положение на направляющей, относительная скорость, относительное ускорение и ускорение Кориолиса",
        "bg": "Транслационни двойки: положение по водача, относителна скорост, относително и Кориолисово ускорение",
        "sl": "Drsni pari: lega na vodilu, relativna hitrost, relativni in Coriolisov pospešek",
    },
    "travel": {"en": "travel", "sr": "пут", "ru": "перемещение", "bg": "преместване", "sl": "pomik"},
    "relative_velocity_short": {"en": "relative velocity", "sr": "релативна брзина", "ru": "относ. скорость", "bg": "относ. скорост", "sl": "relativna hitrost"},
    "relative_acceleration_short": {"en": "relative acceleration", "sr": "релативно убрзање", "ru": "относ. ускорение", "bg": "относ. ускорение", "sl": "relativni pospešek"},
    "coriolis_acceleration": {
        "en": "Coriolis acceleration",
        "sr": "Кориолисово убрзање",
        "ru": "ускорение Кориолиса",
        "bg": "Кориолисово ускорение",
        "sl": "Coriolisov pospešek",
    },
    "turned_from_0": {
        "en": "angle turned by the crank from position 0",
        "sr": "угао заокретања погонског члана од положаја 0",
        "ru": "угол поворота кривошипа от положения 0",
        "bg": "ъгъл на завъртане на манивелата от положение 0",
        "sl": "zasuk ročice od lege 0",
    },
    "driver_position": {
        "en": "position of the driver",
        "sr": "положај погонског члана",
        "ru": "положение ведущего звена",
        "bg": "положение на водещото звено",
        "sl": "lega pogonskega člena",
    },
    "no_assembly": {
        "en": "cannot assemble",
        "sr": "механизам се не може саставити",
        "ru": "механизм не собирается",
        "bg": "механизмът не може да се сглоби",
        "sl": "mehanizma ni mogoče sestaviti",
    },
    "dead_centre": {
        "en": "at a dead centre",
        "sr": "у мртвом положају",
        "ru": "в мёртвом положении",
        "bg": "в мъртво положение",
        "sl": "v mrtvi legi",
    },
    # a note in a cycle diagram: a sweep holds the driver's ω, ε as the scene gives them at every position
    "constant": {"en": "the same at every position", "sr": "исто у сваком положају", "ru": "одинаково во всех положениях",
                 "bg": "еднакво във всички положения", "sl": "enako v vseh legah"},
    "clipped": {
        "en": "beyond the axis near a dead centre",
        "sr": "ван осе, близу мртвог положаја",
        "ru": "за пределами оси, вблизи мёртвого положения",
        "bg": "извън оста, близо до мъртво положение",
        "sl": "zunaj osi, blizu mrtve lege",
    },
    "not_drawn": {
        "en": "not drawn",
        "sr": "нису нацртани",
        "ru": "не построены",
        "bg": "не са построени",
        "sl": "niso narisane",
    },
    "near_dead_centre": {
        "en": "near a dead centre",
        "sr": "близу мртвог положаја",
        "ru": "вблизи мёртвого положения",
        "bg": "близо до мъртво положение",
        "sl": "blizu mrtve lege",
    },
    "construction_lines_angle": {
        "en": "the angle between the group's construction lines",
        "sr": "угао између конструкционих правих групе",
        "ru": "угол между построечными прямыми группы",
        "bg": "ъгълът между построителните прави на групата",
        "sl": "kot med konstrukcijskima premicama skupine",
    },
    "output_extremes": {
        "en": "extreme positions of the output link",
        "sr": "крајњи положаји излазног члана",
        "ru": "крайние положения выходного звена",
        "bg": "крайни положения на изходното звено",
        "sl": "skrajni legi izhodnega člena",
    },
    "coriolis_zero": {
        "en": "Coriolis acceleration aᵏ = 0 at every position (the guide does not turn): not drawn",
        "sr": "Кориолисово убрзање aᵏ = 0 у сваком положају (вођица се не обрће): није нацртано",
        "ru": "ускорение Кориолиса aᵏ = 0 во всех положениях (направляющая не вращается): не построено",
        "bg": "ускорение на Кориолис aᵏ = 0 във всички положения (водачът не се върти): не е построено",
        "sl": "Coriolisov pospešek aᵏ = 0 v vseh legah (vodilo se ne vrti): ni narisan",
    },
    "sheet_positions": {
        "en": "positions drawn",
        "sr": "нацртани положаји",
        "ru": "построенные положения",
        "bg": "построени положения",
        "sl": "narisane lege",
    },
    "components": {"en": "components", "sr": "компоненте", "ru": "составляющие", "bg": "съставящи", "sl": "komponente"},
    "not_solved": {
        "en": "not solved at this position",
        "sr": "није решено у овом положају",
        "ru": "в этом положении решения нет",
        "bg": "в това положение няма решение",
        "sl": "v tej legi ni rešitve",
    },
    "continued": {"en": "(continued)", "sr": "(наставак)", "ru": "(продолжение)", "bg": "(продължение)", "sl": "(nadaljevanje)"},
    "page": {"en": "page", "sr": "страна", "ru": "стр.", "bg": "стр.", "sl": "stran"},
    "scales_per_position": {
        "en": "$k_l$ the same for every position; $k_v$, $k_a$ chosen for each position to fill the page",
        "sr": "$k_l$ исти за све положаје; $k_v$, $k_a$ изабрани за сваки положај",
        "ru": "$k_l$ одинаков для всех положений; $k_v$, $k_a$ выбраны для каждого положения",
        "bg": "$k_l$ еднакъв за всички положения; $k_v$, $k_a$ избрани за всяко положение",
        "sl": "$k_l$ enak za vse lege; $k_v$, $k_a$ izbrana za vsako lego",
    },
    "contents": {"en": "Contents", "sr": "Садржај", "ru": "Содержание", "bg": "Съдържание", "sl": "Vsebina"},
    # --- force plans ---
    "force_plan": {"en": "Force plan", "sr": "План сила", "ru": "План сил", "bg": "План на силите", "sl": "Načrt sil"},
    "free_bodies": {
        "en": "Loads and reactions on the groups",
        "sr": "Оптерећења и реакције на групама",
        "ru": "Нагрузки и реакции групп",
        "bg": "Натоварвания и реакции на групите",
        "sl": "Obremenitve in reakcije na skupinah",
    },
    "not_to_scale": {
        "en": "arrows not to scale",
        "sr": "стрелице нису у размери",
        "ru": "стрелки не в масштабе",
        "bg": "стрелките не са в мащаб",
        "sl": "puščice niso v merilu",
    },
    "guide_origin": {
        "en": "{q}: the point of the guide from which the slider's travel {s} is measured",
        "sr": "{q}: тачка вођице од које се мери пут {s} клизача",
        "ru": "{q} — точка направляющей, от которой отсчитывается перемещение {s} ползуна",
        "bg": "{q} — точка от водача, от която се отчита преместването {s} на плъзгача",
        "sl": "{q}: točka vodila, od katere se meri pot {s} drsnika",
    },
    "free_bodies_coarser": {
        "en": "the free bodies do not fit the page at the plate's {scale}",
        "sr": "слободна тела не стају на страну у размери плана {scale}",
        "ru": "при масштабе плана {scale} свободные тела не помещаются на странице",
        "bg": "при мащаба на чертежа {scale} свободните тела не се побират на страницата",
        "sl": "prosta telesa pri merilu risbe {scale} ne gredo na stran",
    },
    "force_weight": {"en": "weight G", "sr": "тежина G", "ru": "сила тяжести G", "bg": "сила на тежестта G", "sl": "teža G"},
    "force_inertia": {"en": "inertia force", "sr": "сила инерције", "ru": "сила инерции", "bg": "инерционна сила", "sl": "vztrajnostna sila"},
    "force_external": {"en": "given force", "sr": "задата сила", "ru": "заданная сила", "bg": "зададена сила", "sl": "dana sila"},
    "force_reaction": {"en": "reaction R", "sr": "реакција R", "ru": "реакция R", "bg": "реакция R", "sl": "reakcija R"},
    "force_normal": {
        "en": "component Rⁿ along the link",
        "sr": "компонента Rⁿ дуж члана",
        "ru": "составляющая Rⁿ вдоль звена",
        "bg": "съставяща Rⁿ по звеното",
        "sl": "komponenta Rⁿ vzdolž člena",
    },
    "force_tangential": {
        "en": "component Rᵗ ⊥ the link",
        "sr": "компонента Rᵗ ⊥ на члан",
        "ru": "составляющая Rᵗ ⊥ звену",
        "bg": "съставяща Rᵗ ⊥ на звеното",
        "sl": "komponenta Rᵗ ⊥ na člen",
    },
    "force_couple": {"en": "couple", "sr": "спрег", "ru": "пара сил", "bg": "двоица сили", "sl": "dvojica sil"},
    "lever_turned": {
        "en": "the velocity plan turned by 90°, every load at the image of its point",
        "sr": "план брзина заокренут за 90°, свако оптерећење у слици своје тачке",
        "ru": "план скоростей, повёрнутый на 90°, каждая нагрузка в изображении своей точки",
        "bg": "планът на скоростите, завъртян на 90°, всяко натоварване в образа на своята точка",
        "sl": "načrt hitrosti, zasukan za 90°, vsaka obremenitev v sliki svoje točke",
    },
    "lever_turned_ccw": {
        "en": "the velocity plan turned by 90° counter-clockwise (↺) about p, every load at the image of its point",
        "sr": "план брзина заокренут за 90° супротно кретању казаљке на сату (↺) око p, свако оптерећење у слици своје тачке",
        "ru": "план скоростей, повёрнутый на 90° против часовой стрелки (↺) вокруг p, каждая нагрузка в изображении своей точки",
        "bg": "планът на скоростите, завъртян на 90° обратно на часовниковата стрелка (↺) около p, всяко натоварване в образа на своята точка",
        "sl": "načrt hitrosti, zasukan za 90° v nasprotni smeri urinega kazalca (↺) okoli p, vsaka obremenitev v sliki svoje točke",
    },
    "lever_arm_rule": {
        "en": "arm h: from p perpendicular to the line of action; h > 0 when the force turns counter-clockwise about p",
        "sr": "крак h: из p управно на нападну линију; h > 0 кад сила окреће око p супротно кретању казаљке на сату",
        "ru": "плечо h: из p перпендикулярно линии действия; h > 0, если сила вращает вокруг p против часовой стрелки",
        "bg": "рамо h: от p перпендикулярно на линията на действие; h > 0, когато силата върти около p обратно на часовниковата стрелка",
        "sl": "ročica h: iz p pravokotno na nosilko sile; h > 0, ko sila vrti okoli p v nasprotni smeri urinega kazalca",
    },
    "lever_own_scale": {
        "en": "the lever drawn at a scale of its own (the plate's velocity plans: {scale})",
        "sr": "полуга нацртана у сопственој размери (планови брзина на листу: {scale})",
        "ru": "рычаг построен в своём масштабе (планы скоростей на листе: {scale})",
        "bg": "лостът е начертан в собствен мащаб (плановете на скоростите на листа: {scale})",
        "sl": "vzvod narisan v lastnem merilu (načrti hitrosti na listu: {scale})",
    },
    "lever_pair": {
        "en": "the couple as a pair of forces at {points}",
        "sr": "спрег као пар сила у {points}",
        "ru": "пара сил в точках {points} вместо момента",
        "bg": "двоицата като двойка сили в {points}",
        "sl": "dvojica kot par sil v {points}",
    },
    "lever_block_couple": {
        "en": "a block's couple enters the lever as its moment −M·ω/k_v, without an arm",
        "sr": "спрег клизача улази у полугу као свој момент −M·ω/k_v, без крака",
        "ru": "момент ползуна входит в рычаг как момент −M·ω/k_v, без плеча",
        "bg": "моментът на плъзгача влиза в лоста като свой момент −M·ω/k_v, без рамо",
        "sl": "dvojica drsnika vstopi v vzvod kot njen moment −M·ω/k_v, brez ročice",
    },
    "driving_link": {
        "en": "driving link {link} ({kind})",
        "sr": "погонски члан {link} ({kind})",
        "ru": "ведущее звено {link} ({kind})",
        "bg": "водещо звено {link} ({kind})",
        "sl": "pogonski člen {link} ({kind})",
    },
    "crank_kind": {"en": "crank", "sr": "кривај", "ru": "кривошип", "bg": "манивела", "sl": "ročica"},
    "slider_kind": {"en": "slider", "sr": "клизач", "ru": "ползун", "bg": "плъзгач", "sl": "drsnik"},
    "known_loads": {
        "en": "known loads (N → mm)",
        "sr": "позната оптерећења (N → mm)",
        "ru": "известные нагрузки (Н → мм)",
        "bg": "известни натоварвания (N → mm)",
        "sl": "znane obremenitve (N → mm)",
    },
    "carried": {
        "en": "carried from the plan before",
        "sr": "пренето са претходног плана",
        "ru": "перенесено с предыдущего плана",
        "bg": "пренесено от предишния план",
        "sl": "preneseno s prejšnjega načrta",
    },
    "carried_rescaled": {
        "en": "carried from the plan before, drawn there at μ_F = {there} N/mm, here at {here} N/mm",
        "sr": "пренето са претходног плана, тамо у размери μ_F = {there} N/mm, овде {here} N/mm",
        "ru": "перенесено с предыдущего плана, там в масштабе μ_F = {there} Н/мм, здесь {here} Н/мм",
        "bg": "пренесено от предишния план, там в мащаб μ_F = {there} N/mm, тук {here} N/mm",
        "sl": "preneseno s prejšnjega načrta, tam v merilu μ_F = {there} N/mm, tu {here} N/mm",
    },
    "found_first": {
        "en": "found first, from the moments about the middle joint",
        "sr": "одређено прво, из момената за средњи зглоб",
        "ru": "найдено первым, из моментов относительно среднего шарнира",
        "bg": "намерено първо, от моментите спрямо средната става",
        "sl": "določeno najprej, iz momentov okoli srednjega zgloba",
    },
    "lever_arm": {"en": "arm h", "sr": "крак h", "ru": "плечо h", "bg": "рамо h", "sl": "ročica h"},
    "kinetostatics_page": {
        "en": "Kinetostatics: force plans",
        "sr": "Кинетостатика: планови сила",
        "ru": "Кинетостатика: планы сил",
        "bg": "Кинетостатика: планове на силите",
        "sl": "Kinetostatika: načrti sil",
    },
    # --- instant centres (plans centres, the handout's --centres page) ------------
    "instant_centres": {
        "en": "Instant centres",
        "sr": "Тренутни полови брзина",
        "ru": "Мгновенные центры скоростей",
        "bg": "Моментни центрове на скоростите",
        "sl": "Trenutni poli",
    },
    "centres_page": {
        "en": "Instant centres (Kennedy's theorem): the velocities by the method of instant centres",
        "sr": "Тренутни полови брзина по Кенедијевој теореми: трећа метода за брзине",
        "ru": "Мгновенные центры скоростей по теореме Кеннеди: третий метод определения скоростей",
        "bg": "Моментни центрове на скоростите по теоремата на Кенеди: трети метод за скоростите",
        "sl": "Trenutni poli po Kennedyjevem izreku: tretja metoda za hitrosti",
    },
    "kennedy_theorem": {
        "en": "Kennedy's theorem",
        "sr": "Кенедијева теорема",
        "ru": "теорема Кеннеди (о трёх центрах)",
        "bg": "теорема на Кенеди",
        "sl": "Kennedyjev izrek",
    },
    "kennedy_statement": {
        "en": "the three instant centres of any three bodies lie on one straight line",
        "sr": "три тренутна пола било која три члана леже на једној правој",
        "ru": "три мгновенных центра скоростей любых трёх звеньев лежат на одной прямой",
        "bg": "трите моментни центъра на скоростите на всеки три звена лежат на една права",
        "sl": "trije trenutni poli poljubnih treh členov ležijo na isti premici",
    },
    "circle_diagram": {
        "en": "circle diagram",
        "sr": "кружни дијаграм",
        "ru": "круговая диаграмма",
        "bg": "кръгова диаграма",
        "sl": "krožni diagram",
    },
    "circle_diagram_legend": {
        "en": "solid lines: centres at the kinematic pairs;\ndashed: found by Kennedy's theorem",
        "sr": "пуне линије: полови у кинематичким паровима;\nиспрекидане: по Кенедијевој теореми",
        "ru": "сплошные линии: центры в кинематических парах;\nштриховые: по теореме Кеннеди",
        "bg": "плътни линии: центрове в кинематичните двойки;\nпрекъснати: по теоремата на Кенеди",
        "sl": "polne črte: poli v kinematičnih parih;\nčrtkane: po Kennedyjevem izreku",
    },
    "centres_legend": {
        "en": "circles: centres at the kinematic pairs; dots: found by Kennedy's theorem on the dashed lines",
        "sr": "кружићи: полови у кинематичким паровима; тачке: нађени по Кенедијевој теореми на испрекиданим правама",
        "ru": "кружки: центры в кинематических парах; точки: найдены по теореме Кеннеди на штриховых прямых",
        "bg": "кръгчета: центрове в кинематичните двойки; точки: намерени по теоремата на Кенеди върху прекъснатите прави",
        "sl": "krožci: poli v kinematičnih parih; pike: najdeni po Kennedyjevem izreku na črtkanih premicah",
    },
    "centres_edge_legend": {
        "en": "an arrow at the edge points to a centre off the drawing: its distance beyond the arrow's tip in mm of the drawing (× kₗ = metres), or ∞ at infinity",
        "sr": "стрелица на ивици показује пол ван цртежа: његово растојање иза врха стрелице у mm цртежа (× kₗ = метри), или ∞ у бесконачности",
        "ru": "стрелка у края указывает на центр за пределами чертежа: его расстояние за остриём стрелки в мм чертежа (× kₗ = метры), или ∞ в бесконечности",
        "bg": "стрелка в края сочи към център извън чертежа: разстоянието му след върха на стрелката в mm от чертежа (× kₗ = метри), или ∞ в безкрайността",
        "sl": "puščica na robu kaže na pol zunaj risbe: njegova razdalja za konico puščice v mm risbe (× kₗ = metri), ali ∞ v neskončnosti",
    },
    "centre_undetermined": {"en": "undetermined", "sr": "неодређен", "ru": "не определён", "bg": "неопределен", "sl": "nedoločen"},
    "centre_undetermined_why": {
        "en": "its Kennedy lines coincide at this position (the velocities do not need it)",
        "sr": "његове Кенедијеве праве се у овом положају поклапају (брзине га не захтевају)",
        "ru": "его прямые Кеннеди в этом положении совпадают (для скоростей он не нужен)",
        "bg": "правите на Кенеди за него съвпадат в това положение (скоростите не се нуждаят от него)",
        "sl": "njegove Kennedyjeve premice v tej legi sovpadajo (hitrosti ga ne potrebujejo)",
    },
    "centres_read_exact": {
        "en": "ω and v computed from the exact centres, not read off the drawing: centres coincide on the drawing at this kₗ, on every path of centres",
        "sr": "ω и v израчунати из тачних положаја полова, не очитани са цртежа: полови се на цртежу при овом kₗ поклапају, на сваком путу преко полова",
        "ru": "ω и v вычислены по точным положениям центров, а не измерены на чертеже: центры на чертеже при этом kₗ совпадают, на любом пути через центры",
        "bg": "ω и v са изчислени по точните положения на центровете, не са измерени от чертежа: центровете на чертежа при този kₗ съвпадат, по всеки път през центровете",
        "sl": "ω in v izračunani iz natančnih leg polov, ne odčitani z risbe: poli na risbi pri tem kₗ sovpadajo, na vsaki poti prek polov",
    },
    "by_centres": {"en": "instant centres", "sr": "тренутни полови", "ru": "мгн. центры", "bg": "моментни центрове", "sl": "trenutni poli"},
    "centres_results": {
        "en": "Velocities from the instant centres and analytic values",
        "sr": "Брзине из тренутних полова и аналитичке вредности",
        "ru": "Скорости по мгновенным центрам и аналитические значения",
        "bg": "Скорости от моментните центрове и аналитични стойности",
        "sl": "Hitrosti iz trenutnih polov in analitične vrednosti",
    },
    "centres_omega_rule": {
        "en": "Angular velocities from the instant centres, link by link from the driver, through the centre common to two links",
        "sr": "Угаоне брзине из тренутних полова, члан по члан од погонског, преко пола заједничког за два члана",
        "ru": "Угловые скорости по мгновенным центрам, звено за звеном от ведущего, через общий центр двух звеньев",
        "bg": "Ъглови скорости от моментните центрове, звено по звено от водещото, чрез общия център на две звена",
        "sl": "Kotne hitrosti iz trenutnih polov, člen za členom od pogonskega, prek skupnega pola dveh členov",
    },
    "centres_v_rule": {
        "en": "Velocity of a point from the centre its link turns about",
        "sr": "Брзина тачке из пола око ког се окреће њен члан",
        "ru": "Скорость точки по центру, вокруг которого поворачивается её звено",
        "bg": "Скорост на точка от центъра, около който се завърта звеното ѝ",
        "sl": "Hitrost točke iz pola, okoli katerega se vrti njen člen",
    },
    # the handout's words for a sliding driver and its centres' pages (issue 20, plate-words)
    "centres_omega_rule_linear": {
        "en": "Angular velocities from the driver's velocity and the instant centres",
        "sr": "Угаоне брзине из брзине погонског члана и тренутних полова",
        "ru": "Угловые скорости по скорости ведущего звена и мгновенным центрам",
        "bg": "Ъглови скорости от скоростта на водещото звено и моментните центрове",
        "sl": "Kotne hitrosti iz hitrosti pogonskega člena in trenutnih polov",
    },
    # the sign of the ratio theorem and the step through a translating link, on the centres' method page
    "centres_sign": {"en": "Sense of rotation", "sr": "Смер обртања", "ru": "Направление вращения", "bg": "Посока на въртене",
                     "sl": "Smisel vrtenja"},
    "centres_sign_rule": {
        "en": "{omega_j} turns the same way as {omega_k} when {pjk} lies outside the segment {segment}, the opposite way when it lies inside it (a minus sign in the tables)",
        "sr": "{omega_j} има исти смер као {omega_k} када {pjk} лежи ван дужи {segment}, супротан када лежи унутар ње (знак минус у табелама)",
        "ru": "{omega_j} того же направления, что и {omega_k}, если {pjk} лежит вне отрезка {segment}, и противоположного, если внутри него (знак минус в таблицах)",
        "bg": "{omega_j} има посоката на {omega_k}, когато {pjk} лежи извън отсечката {segment}, и обратната, когато лежи в нея (знак минус в таблиците)",
        "sl": "{omega_j} ima isti smisel kot {omega_k}, kadar {pjk} leži zunaj daljice {segment}, in nasprotnega, kadar leži znotraj nje (predznak minus v tabelah)",
    },
    # the sign of ω found through a link that translates (its v a magnitude), on the centres' method page
    "centres_sign_rule_translating": {
        "en": "through a link that translates, {formula} with {v} its magnitude: + when {v}, at {p}, turns anticlockwise about {p1}, − (in the tables) when clockwise",
        "sr": "преко члана који се креће транслаторно, {formula}, где је {v} интензитет: + када {v} у {p} обрће око {p1} супротно од казаљке на сату, − (у табелама) када у смеру казаљке",
        "ru": "через звено, движущееся поступательно, {formula}, где {v} — модуль: +, если {v} в {p} поворачивает вокруг {p1} против часовой стрелки, − (в таблицах), если по часовой",
        "bg": "чрез звено, което се движи постъпателно, {formula}, където {v} е големината: +, когато {v} в {p} върти около {p1} обратно на часовниковата стрелка, − (в таблиците), когато по нея",
        "sl": "prek člena, ki se giblje translatorno, {formula}, kjer je {v} velikost: +, kadar {v} v {p} vrti okoli {p1} v nasprotni smeri urinega kazalca, − (v tabelah), kadar v smeri urinega kazalca",
    },
    "centres_translation_rule": {
        "en": "A link that translates ({p1j} at infinity, {omega_j} = 0) moves as its centre with a link {k}; through it the next link {l} turns",
        "sr": "Члан који се креће транслаторно ({p1j} у бесконачности, {omega_j} = 0) креће се као његов пол са чланом {k}; преко њега се обрће следећи члан {l}",
        "ru": "Звено, движущееся поступательно ({p1j} в бесконечности, {omega_j} = 0), движется как его центр со звеном {k}; через него вращается следующее звено {l}",
        "bg": "Звено, което се движи постъпателно ({p1j} в безкрайността, {omega_j} = 0), се движи като центъра си със звеното {k}; чрез него се върти следващото звено {l}",
        "sl": "Člen, ki se giblje translatorno ({p1j} v neskončnosti, {omega_j} = 0), se giblje kot njegov pol s členom {k}; prek njega se vrti naslednji člen {l}",
    },
    "over_driver_stroke": {"en": "over the driver's stroke", "sr": "током хода погонског члана", "ru": "за ход ведущего звена",
                           "bg": "за хода на водещото звено", "sl": "med hodom pogonskega člena"},
    "driver_stroke_ends": {"en": "ends of the driver's stroke", "sr": "крајеви хода погонског члана",
                           "ru": "концы хода ведущего звена", "bg": "краищата на хода на водещото звено",
                           "sl": "konca hoda pogonskega člena"},
    "driver_stroke": {"en": "the driver's stroke", "sr": "ход погонског члана", "ru": "ход ведущего звена",
                      "bg": "ходът на водещото звено", "sl": "hod pogonskega člena"},
    "centre_column": {"en": "centre", "sr": "пол", "ru": "центр", "bg": "център", "sl": "pol"},
    "found_column": {"en": "found", "sr": "како је нађен", "ru": "как найден", "bg": "как е намерен", "sl": "kako je najden"},
    "centre_at_pin": {"en": "at the pin {pin}", "sr": "у зглобу {pin}", "ru": "в шарнире {pin}", "bg": "в шарнира {pin}",
                      "sl": "v zgibu {pin}"},
    "centre_perpendicular_guide": {"en": "at infinity, perpendicular to the guide on link {link}", "sr": "у бесконачности, управно на вођицу на члану {link}",
                                   "ru": "в бесконечности, перпендикулярно направляющей на звене {link}",
                                   "bg": "в безкрайността, перпендикулярно на водача на звено {link}", "sl": "v neskončnosti, pravokotno na vodilo na členu {link}"},
    "centre_perpendicular_frame_guide": {"en": "at infinity, perpendicular to the frame's guide", "sr": "у бесконачности, управно на вођицу на постољу",
                                         "ru": "в бесконечности, перпендикулярно направляющей стойки",
                                         "bg": "в безкрайността, перпендикулярно на водача на стойката", "sl": "v neskončnosti, pravokotno na vodilo ogrodja"},
    "centres_order": {"en": "The order of finding the centres", "sr": "Редослед налажења полова", "ru": "Порядок нахождения центров",
                      "bg": "Ред на намиране на центровете", "sl": "Vrstni red iskanja polov"},
    "one_way_stroke": {"en": "one way: no return stroke, no coefficient of the average speed increase K", "sr": "у једном смеру: без повратног хода, без коефицијента повећања средње брзине K",
                       "ru": "в одну сторону: без обратного хода, без коэффициента изменения средней скорости K", "bg": "в една посока: без обратен ход, без коефициент на изменение на средната скорост K",
                       "sl": "v eno smer: brez povratnega hoda, brez koeficienta povečanja srednje hitrosti K"},
    # readings of a plan (issue 10 §2): what a student measures and computes
    "readings": {
        "en": "readings",
        "sr": "очитавања",
        "ru": "отсчёты",
        "bg": "отчитания",
        "sl": "odčitki",
    },
    "segment": {"en": "segment", "sr": "дуж", "ru": "отрезок", "bg": "отсечка", "sl": "daljica"},
    # --- forces ---
    "kinetostatics": {
        "en": "Kinetostatic analysis",
        "sr": "Кинетостатичка анализа",
        "ru": "Кинетостатический анализ",
        "bg": "Кинетостатичен анализ",
        "sl": "Kinetostatična analiza",
    },
    "loads": {"en": "Loads", "sr": "Оптерећења", "ru": "Нагрузки", "bg": "Натоварвания", "sl": "Obremenitve"},
    "reactions": {
        "en": "Reactions in the kinematic pairs",
        "sr": "Реакције у кинематским паровима",
        "ru": "Реакции в кинематических парах",
        "bg": "Реакции в кинематичните двойки",
        "sl": "Reakcije v kinematičnih parih",
    },
    "reaction_convention": {
        "en": "R_ij: the force of link i on link j ({frame}: the frame)",
        "sr": "R_ij: сила којом члан i делује на члан j ({frame}: постоље)",
        "ru": "R_ij: сила действия звена i на звено j ({frame}: стойка)",
        "bg": "R_ij: сила, с която звено i действа на звено j ({frame}: стойка)",
        "sl": "R_ij: sila, s katero člen i deluje na člen j ({frame}: ogrodje)",
    },
    "balancing_moment": {
        "en": "Balancing moment",
        "sr": "Уравнотежни момент",
        "ru": "Уравновешивающий момент",
        "bg": "Уравновесяващ момент",
        "sl": "Uravnotežilni moment",
    },
    "balancing_force": {
        "en": "Balancing force",
        "sr": "Уравнотежна сила",
        "ru": "Уравновешивающая сила",
        "bg": "Уравновесяваща сила",
        "sl": "Uravnotežilna sila",
    },
    "joukowski_lever": {
        "en": "Joukowski's lever",
        "sr": "Жуковљева полуга",
        "ru": "Рычаг Жуковского",
        "bg": "Лост на Жуковски",
        "sl": "Žukovskijev vzvod",
    },
    "force_plans": {"en": "force plans", "sr": "планови сила", "ru": "планы сил", "bg": "планове на силите", "sl": "načrti sil"},
    # which method a value printed on its own line came from (M_b under the driver's plan and under the lever)
    "from_force_plans": {"en": "from the force plans", "sr": "из планова сила", "ru": "по планам сил", "bg": "от плановете на силите",
                         "sl": "iz načrtov sil"},
    "from_lever": {"en": "from Joukowski's lever", "sr": "из Жуковљеве полуге", "ru": "по рычагу Жуковского", "bg": "от лоста на Жуковски",
                   "sl": "iz Žukovskijevega vzvoda"},
    "weight": {"en": "weight", "sr": "тежина", "ru": "сила тяжести", "bg": "тегло", "sl": "teža"},
    "inertia_force": {"en": "inertia force", "sr": "сила инерције", "ru": "сила инерции", "bg": "инерционна сила", "sl": "vztrajnostna sila"},
    "inertia_couple": {
        "en": "inertia couple",
        "sr": "момент сила инерције",
        "ru": "момент сил инерции",
        "bg": "момент на инерционните сили",
        "sl": "moment vztrajnostnih sil",
    },
    "external_force": {"en": "force", "sr": "сила", "ru": "сила", "bg": "сила", "sl": "sila"},
    "resistance": {"en": "resistance", "sr": "сила отпора", "ru": "сила сопротивления", "bg": "съпротивителна сила", "sl": "sila upora"},
    "useful_resistance": {
        "en": "useful resistance",
        "sr": "сила корисног отпора",
        "ru": "сила полезного сопротивления",
        "bg": "сила на полезното съпротивление",
        "sl": "sila koristnega upora",
    },
    "couple": {"en": "couple", "sr": "спрег сила", "ru": "пара сил", "bg": "двоица сили", "sl": "dvojica sil"},
    "normal_force": {"en": "normal force", "sr": "нормална сила", "ru": "нормальная сила", "bg": "нормална сила", "sl": "normalna sila"},
    "point_of_action": {"en": "point of action", "sr": "нападна тачка", "ru": "точка приложения", "bg": "приложна точка", "sl": "prijemališče"},
    "kind": {"en": "kind", "sr": "врста", "ru": "вид", "bg": "вид", "sl": "vrsta"},
    "power_balance": {"en": "Power balance", "sr": "Биланс снага", "ru": "Баланс мощностей", "bg": "Баланс на мощностите", "sl": "Bilanca moči"},
    "residual": {"en": "residual", "sr": "остатак", "ru": "невязка", "bg": "остатък", "sl": "ostanek"},
    "ccw_positive": {
        "en": "counter-clockwise positive",
        "sr": "позитиван супротно кретању казаљке на сату",
        "ru": "положителен против часовой стрелки",
        "bg": "положителен обратно на часовниковата стрелка",
        "sl": "pozitiven v nasprotni smeri urinega kazalca",
    },
    "along_guide": {
        "en": "along the driver's guide",
        "sr": "дуж вођице погонског члана",
        "ru": "вдоль направляющей ведущего звена",
        "bg": "по направляващата на водещото звено",
        "sl": "vzdolž vodila pogonskega člena",
    },
    "lever_left_out": {
        "en": "Joukowski's lever left out: the driver is at rest",
        "sr": "Жуковљева полуга изостављена: погонски члан мирује",
        "ru": "Рычаг Жуковского не построен: ведущее звено неподвижно",
        "bg": "Лостът на Жуковски е пропуснат: водещото звено е неподвижно",
        "sl": "Žukovskijev vzvod izpuščen: pogonski člen miruje",
    },
    # --- the plate (plans.pages) -------------------------------------------------------------
    "plate_title": {
        "en": "Kinematic analysis of the mechanism",
        "sr": "Кинематичка анализа механизма",
        "ru": "Кинематический анализ механизма",
        "bg": "Кинематичен анализ на механизма",
        "sl": "Kinematična analiza mehanizma",
    },
    "drawn_by": {"en": "Drawn by", "sr": "Цртао", "ru": "Разработал", "bg": "Изработил", "sl": "Risal"},
    "checked_by": {"en": "Checked by", "sr": "Прегледао", "ru": "Проверил", "bg": "Проверил", "sl": "Pregledal"},
    "date": {"en": "Date", "sr": "Датум", "ru": "Дата", "bg": "Дата", "sl": "Datum"},
    "institution": {"en": "Institution", "sr": "Установа", "ru": "Учебное заведение", "bg": "Учебно заведение", "sl": "Ustanova"},
    "index_number": {"en": "Student no.", "sr": "Бр. индекса", "ru": "№ зач. книжки", "bg": "Фак. №", "sl": "Vpisna št."},
    "similar_images": {"en": "Images by similarity", "sr": "Слике по сличности", "ru": "Изображения по подобию", "bg": "Образи по подобие",
                       "sl": "Slike po podobnosti"},
    "by_similarity": {"en": "by similarity", "sr": "по сличности", "ru": "по подобию", "bg": "по подобие", "sl": "po podobnosti"},
    "student_group": {"en": "Group", "sr": "Група", "ru": "Группа", "bg": "Група", "sl": "Skupina"},
    "sheet": {"en": "Sheet", "sr": "Лист", "ru": "Лист", "bg": "Лист", "sl": "List"},
    "of_sheets": {"en": "of", "sr": "од", "ru": "из", "bg": "от", "sl": "od"},
    "underlines": {
        "en": "underlined once: direction known; twice: magnitude and direction known; the sought vector (on the left) not underlined",
        "sr": "подвучено једном: познат правац; двапут: познати интензитет и правац; тражени вектор (лево) није подвучен",
        "ru": "подчёркнуто один раз — известно направление; дважды — известны величина и направление; искомый вектор (слева) не подчёркнут",
        "bg": "подчертано веднъж — известно направление; два пъти — известни големина и направление; търсеният вектор (вляво) не е подчертан",
        "sl": "podčrtano enkrat: znana smer; dvakrat: znani velikost in smer; iskani vektor (levo) ni podčrtan",
    },
    "velocity_plans": {"en": "Velocity plans", "sr": "Планови брзина", "ru": "Планы скоростей", "bg": "Планове на скоростите", "sl": "Načrti hitrosti"},
    "acceleration_plans": {"en": "Acceleration plans", "sr": "Планови убрзања", "ru": "Планы ускорений", "bg": "Планове на ускоренията", "sl": "Načrti pospeškov"},
    "each_from_its_pole": {
        "en": "each from its own pole",
        "sr": "сваки из свог пола",
        "ru": "каждый из своего полюса",
        "bg": "всеки от своя полюс",
        "sl": "vsak iz svojega pola",
    },
    "scales_each_position": {
        "en": "scale factors chosen for each position",
        "sr": "размере изабране за сваки положај",
        "ru": "масштабы выбраны для каждого положения",
        "bg": "мащабите са избрани за всяко положение",
        "sl": "merila izbrana za vsako lego",
    },
    "idle_stroke": {"en": "idle stroke", "sr": "повратни ход", "ru": "холостой ход", "bg": "празен ход", "sl": "povratni hod"},
    "assembly": {"en": "Assembly of the groups", "sr": "Склоп група", "ru": "Сборка групп", "bg": "Сглобяване на групите", "sl": "Sestav skupin"},
    "group": {"en": "group", "sr": "група", "ru": "группа", "bg": "група", "sl": "skupina"},
    "assembly_side": {
        "en": "{c} to the {side} of the line {b}{d}, looking from {b} towards {d}",
        "sr": "{c} {side} од праве {b}{d}, гледано од {b} ка {d}",
        "ru": "{c} {side} от прямой {b}{d}, если смотреть от {b} к {d}",
        "bg": "{c} {side} от правата {b}{d}, гледано от {b} към {d}",
        "sl": "{c} {side} od premice {b}{d}, gledano od {b} proti {d}",
    },
    "left": {"en": "left", "sr": "лево", "ru": "слева", "bg": "вляво", "sl": "levo"},
    "right": {"en": "right", "sr": "десно", "ru": "справа", "bg": "вдясно", "sl": "desno"},
    "assembly_slider_side": {
        "en": "slider {c} {where} {b}",
        "sr": "клизач {c} {where} {b}",
        "ru": "ползун {c} {where} {b}",
        "bg": "плъзгач {c} {where} {b}",
        "sl": "drsnik {c} {where} {b}",
    },
    "right_of": {"en": "to the right of", "sr": "десно од", "ru": "справа от", "bg": "вдясно от", "sl": "desno od"},
    "left_of": {"en": "to the left of", "sr": "лево од", "ru": "слева от", "bg": "вляво от", "sl": "levo od"},
    "above": {"en": "above", "sr": "изнад", "ru": "выше", "bg": "над", "sl": "nad"},
    "below": {"en": "below", "sr": "испод", "ru": "ниже", "bg": "под", "sl": "pod"},
    "assembly_along": {  # {key}: the guide's name as it reads after "along the" (its "of" form, [names])
        "en": "slider {c} {where} {b} along the {key}",
        "sr": "клизач {c} {where} {b} дуж {key}",
        "ru": "ползун {c} {where} {b} вдоль {key}",
        "bg": "плъзгач {c} {where} {b} по направлението на {key}",
        "sl": "drsnik {c} {where} {b} vzdolž {key}",
    },
    "ahead_of": {"en": "ahead of", "sr": "испред", "ru": "впереди", "bg": "пред", "sl": "pred"},
    "behind": {"en": "behind", "sr": "иза", "ru": "позади", "bg": "зад", "sl": "za"},
    "assembly_directed": {  # {key}: the guide's name as it reads after "direction of the" (its "of" form)
        "en": "direction of the {key}: from {a} towards {b}",
        "sr": "смер {key}: од {a} ка {b}",
        "ru": "направление {key}: от {a} к {b}",
        "bg": "посока на {key}: от {a} към {b}",
        "sl": "smer {key}: od {a} proti {b}",
    },
    "assembly_directed_points": {
        "en": "direction of the {key}: {points}",
        "sr": "смер {key}: {points}",
        "ru": "направление {key}: {points}",
        "bg": "посока на {key}: {points}",
        "sl": "smer {key}: {points}",
    },
    "open_four_bar": {"en": "open four-bar", "sr": "отворени зглавкасти четвороугао", "ru": "открытый шарнирный четырёхзвенник",
                      "bg": "отворен шарнирен четиризвенник", "sl": "odprti štirizgibni mehanizem"},
    "crossed_four_bar": {"en": "crossed four-bar", "sr": "укрштени зглавкасти четвороугао", "ru": "перекрещенный шарнирный четырёхзвенник",
                         "bg": "кръстосан шарнирен четиризвенник", "sl": "prekrižani štirizgibni mehanizem"},
    "comparison": {
        "en": "Graphical and analytic values",
        "sr": "Графичке и аналитичке вредности",
        "ru": "Графические и аналитические значения",
        "bg": "Графични и аналитични стойности",
        "sl": "Grafične in analitične vrednosti",
    },
    # --- kinematic diagrams ---
    "kinematic_diagrams": {
        "en": "Kinematic diagrams of the output link",
        "sr": "Кинематски дијаграми излазног члана",
        "ru": "Кинематические диаграммы выходного звена",
        "bg": "Кинематични диаграми на изходното звено",
        "sl": "Kinematični diagrami izhodnega člena",
    },
    "graphical_differentiation": {
        "en": "graphical differentiation by the method of chords",
        "sr": "графичко диференцирање методом тетива",
        "ru": "графическое дифференцирование методом хорд",
        "bg": "графично диференциране по метода на хордите",
        "sl": "grafično odvajanje z metodo tetiv",
    },
    "output_slider": {
        "en": "output link: slider",
        "sr": "излазни члан: клизач",
        "ru": "выходное звено: ползун",
        "bg": "изходно звено: плъзгач",
        "sl": "izhodni člen: drsnik",
    },
    "output_rocker": {
        "en": "output link: rocker",
        "sr": "излазни члан: клацкач",
        "ru": "выходное звено: коромысло",
        "bg": "изходно звено: кобилица",
        "sl": "izhodni člen: nihalka",
    },
    "displacement": {"en": "displacement", "sr": "померање", "ru": "перемещение", "bg": "преместване", "sl": "pomik"},
    "cycle_time": {
        "en": "time of one cycle",
        "sr": "време једног циклуса",
        "ru": "время одного цикла",
        "bg": "време на един цикъл",
        "sl": "čas enega cikla",
    },
    "abscissa_length": {
        "en": "length of the abscissa",
        "sr": "дужина апсцисе",
        "ru": "длина оси абсцисс",
        "bg": "дължина на абсцисата",
        "sl": "dolžina abscise",
    },
    "chord": {"en": "chord", "sr": "тетива", "ru": "хорда", "bg": "хорда", "sl": "tetiva"},
    "ray": {
        "en": "ray from the pole, parallel to the chord",
        "sr": "зрак из пола, паралелан тетиви",
        "ru": "луч из полюса, параллельный хорде",
        "bg": "лъч от полюса, успореден на хордата",
        "sl": "žarek iz pola, vzporeden s tetivo",
    },
    "chords_curve": {
        "en": "curve through the points",
        "sr": "крива кроз тачке",
        "ru": "кривая через точки",
        "bg": "крива през точките",
        "sl": "krivulja skozi točke",
    },
    "analytic_curve": {
        "en": "analytic, for comparison",
        "sr": "аналитички, за поређење",
        "ru": "аналитически, для сравнения",
        "bg": "аналитично, за сравнение",
        "sl": "analitično, za primerjavo",
    },
    "diagrams_table": {
        "en": "The output link at every position: from the diagrams, from the plans and analytic",
        "sr": "Излазни члан у сваком положају: из дијаграма, из планова и аналитички",
        "ru": "Выходное звено во всех положениях: по диаграммам, по планам и аналитически",
        "bg": "Изходното звено във всяко положение: от диаграмите, от плановете и аналитично",
        "sl": "Izhodni člen v vsaki legi: iz diagramov, iz načrtov in analitično",
    },
    "from_diagram": {"en": "diagr.", "sr": "дијагр.", "ru": "диагр.", "bg": "диагр.", "sl": "diagr."},
    "from_plans": {"en": "plan", "sr": "план", "ru": "план", "bg": "план", "sl": "načrt"},
    "from_analytic": {"en": "analyt.", "sr": "аналит.", "ru": "аналит.", "bg": "аналит.", "sl": "analit."},
    "diagram_error_note": {
        "en": "δ: error against the analytic value, in % of its largest magnitude over the positions",
        "sr": "δ: грешка према аналитичкој вредности, у % њене највеће апсолутне вредности у положајима",
        "ru": "δ: погрешность относительно аналитического значения, в % от его наибольшей величины по положениям",
        "bg": "δ: грешка спрямо аналитичната стойност, в % от най-голямата ѝ големина в положенията",
        "sl": "δ: napaka glede na analitično vrednost, v % njene največje absolutne vrednosti v legah",
    },
    "method_of_tangents": {
        "en": "method of tangents",
        "sr": "метода тангенти",
        "ru": "метод касательных",
        "bg": "метод на допирателните",
        "sl": "metoda tangent",
    },
    "kd_no_output": {
        "en": "the mechanism has no output slider (on a guide of the frame) or rocker (turning about a frame point); name one with [output] link",
        "sr": "механизам нема излазни клизач (на вођици постоља) ни клацкач (који се обрће око тачке постоља); наведите га са [output] link",
        "ru": "у механизма нет выходного ползуна (на направляющей стойки) или коромысла (вращающегося вокруг точки стойки); укажите его в [output] link",
        "bg": "механизмът няма изходен плъзгач (по водач на стойката) или кобилица (въртяща се около точка на стойката); посочете го с [output] link",
        "sl": "mehanizem nima izhodnega drsnika (na vodilu ogrodja) ali nihalke (ki se vrti okoli točke ogrodja); navedite ga z [output] link",
    },
    "kd_unsolved": {
        "en": "the mechanism is not solved at positions {positions}: graphical differentiation joins neighbouring positions and needs every one",
        "sr": "механизам није решен у положајима {positions}: графичко диференцирање спаја суседне положаје и потребан му је сваки",
        "ru": "механизм не решается в положениях {positions}: графическое дифференцирование соединяет соседние положения, и нужны все",
        "bg": "механизмът не е решен в положенията {positions}: графичното диференциране свързва съседни положения и са нужни всички",
        "sl": "mehanizem ni rešen v legah {positions}: grafično odvajanje povezuje sosednje lege in potrebuje vse",
    },
    "kd_not_drawn": {
        "en": "The diagrams are not drawn",
        "sr": "Дијаграми нису нацртани",
        "ru": "Диаграммы не построены",
        "bg": "Диаграмите не са построени",
        "sl": "Diagrami niso narisani",
    },
    "kd_mu_not_k": {
        "en": "{mu}: the scales of these diagrams, not the plans' {k}",
        "sr": "{mu}: размере ових дијаграма, а не размере планова {k}",
        "ru": "{mu}: масштабы этих диаграмм, а не масштабы планов {k}",
        "bg": "{mu}: мащабите на тези диаграми, а не мащабите на плановете {k}",
        "sl": "{mu}: merila teh diagramov, ne merila načrtov {k}",
    },
    "chords_order": {
        "en": "the error of the chords falls as Δt²: with twice the positions, to about a quarter",
        "sr": "грешка метода тетива опада као Δt²: са двоструко више положаја на око четвртину",
        "ru": "погрешность метода хорд убывает как Δt²: при вдвое большем числе положений примерно вчетверо",
        "bg": "грешката на метода на хордите намалява като Δt²: при двойно повече положения до около една четвърт",
        "sl": "napaka metode tetiv pada kot Δt²: pri dvakrat več legah na približno četrtino",
    },
    # --- lecture page ---------------------------------------------------------------
    "lecture_title": {
        "en": "Mechanism, velocity plan and acceleration plan over the cycle",
        "sr": "Механизам, план брзина и план убрзања током циклуса",
        "ru": "Механизм, план скоростей и план ускорений за цикл",
        "bg": "Механизъм, план на скоростите и план на ускоренията за един цикъл",
        "sl": "Mehanizem, načrt hitrosti in načrt pospeškov v enem ciklu",
    },
    "lecture_play": {"en": "Play", "sr": "Покрени", "ru": "Пуск", "bg": "Пусни", "sl": "Predvajaj"},
    "lecture_pause": {"en": "Pause", "sr": "Заустави", "ru": "Пауза", "bg": "Пауза", "sl": "Ustavi"},
    "lecture_previous": {
        "en": "previous position",
        "sr": "претходни положај",
        "ru": "предыдущее положение",
        "bg": "предишно положение",
        "sl": "prejšnja lega",
    },
    "lecture_next": {
        "en": "next position",
        "sr": "следећи положај",
        "ru": "следующее положение",
        "bg": "следващо положение",
        "sl": "naslednja lega",
    },
    "lecture_speed": {"en": "speed", "sr": "брзина приказа", "ru": "скорость показа", "bg": "скорост на показване", "sl": "hitrost prikaza"},
    "lecture_keys": {
        "en": "keys: ← → one position, space play or pause, Home and End the first and the last position",
        "sr": "тастери: ← → један положај, размак покрени или заустави, Home и End први и последњи положај",
        "ru": "клавиши: ← → на одно положение, пробел пуск или пауза, Home и End первое и последнее положение",
        "bg": "клавиши: ← → с едно положение, интервал пусни или пауза, Home и End първото и последното положение",
        "sl": "tipke: ← → za eno lego, preslednica predvajaj ali ustavi, Home in End prva in zadnja lega",
    },
    "lecture_values": {
        "en": "Values at this position",
        "sr": "Вредности у овом положају",
        "ru": "Значения в этом положении",
        "bg": "Стойности в това положение",
        "sl": "Vrednosti v tej legi",
    },
    "lecture_unit": {"en": "unit", "sr": "јединица", "ru": "ед. изм.", "bg": "мерна единица", "sl": "enota"},
    "lecture_legend": {"en": "Legend", "sr": "Легенда", "ru": "Условные обозначения", "bg": "Легенда", "sl": "Legenda"},
    "lecture_cursor": {
        "en": "the red line is the position shown",
        "sr": "црвена линија је приказани положај",
        "ru": "красная линия — показанное положение",
        "bg": "червената линия е показаното положение",
        "sl": "rdeča črta je prikazana lega",
    },
    "lecture_relative_sign": {
        "en": "vʳ, aʳ of {pair}: the slider's motion relative to its guide, positive along the guide line “{line}” of link {guide} in the line's own direction (at {angle}° to the link's x axis, as the scene gives it)",
        "sr": "vʳ, aʳ у {pair}: кретање клизача у односу на вођицу, позитивно дуж линије вођења „{line}” члана {guide} у њеном смеру (под {angle}° према x оси члана, како је задата у сцени)",
        "ru": "vʳ, aʳ в {pair}: движение ползуна относительно направляющей, положительно вдоль линии «{line}» звена {guide} в её направлении (под {angle}° к оси x звена, как задано в сцене)",
        "bg": "vʳ, aʳ в {pair}: движението на плъзгача спрямо водача, положително по линията „{line}“ на звено {guide} в нейната посока (под {angle}° спрямо оста x на звеното, както е зададена в сцената)",
        "sl": "vʳ, aʳ v {pair}: gibanje drsnika glede na vodilo, pozitivno vzdolž vodilne črte »{line}« člena {guide} v njeni smeri (pod {angle}° glede na os x člena, kot jo podaja scena)",
    },
    "lecture_relative_sign_frame": {
        "en": "vʳ, aʳ of {pair}: the slider's motion relative to its guide, positive along the frame's guide line “{line}” in the line's own direction (at {angle}° to the x axis)",
        "sr": "vʳ, aʳ у {pair}: кретање клизача у односу на вођицу, позитивно дуж линије вођења „{line}” постоља у њеном смеру (под {angle}° према оси x)",
        "ru": "vʳ, aʳ в {pair}: движение ползуна относительно направляющей, положительно вдоль линии «{line}» стойки в её направлении (под {angle}° к оси x)",
        "bg": "vʳ, aʳ в {pair}: движението на плъзгача спрямо водача, положително по линията „{line}“ на стойката в нейната посока (под {angle}° спрямо оста x)",
        "sl": "vʳ, aʳ v {pair}: gibanje drsnika glede na vodilo, pozitivno vzdolž vodilne črte »{line}« ogrodja v njeni smeri (pod {angle}° glede na os x)",
    },
    "lecture_digits": {
        "en": "graphical values to the plans' reading precision ({precision} mm of a plan)",
        "sr": "графичке вредности на тачност очитавања планова ({precision} mm плана)",
        "ru": "графические значения с точностью отсчёта по планам ({precision} mm плана)",
        "bg": "графичните стойности с точността на отчитане от плановете ({precision} mm от плана)",
        "sl": "grafične vrednosti na natančnost odčitavanja z načrtov ({precision} mm načrta)",
    },
    # --- forces over the cycle ---
    "forces_cycle_title": {"en": "The driving moment and the crank bearing's reaction over the cycle",
                           "sr": "Погонски момент и реакција у лежишту криваје током циклуса",
                           "ru": "Движущий момент и реакция в опоре кривошипа за цикл",
                           "bg": "Движещ момент и реакция в опората на манивелата за цикъла",
                           "sl": "Pogonski moment in reakcija v ležaju ročice med ciklom"},
    "driving_moment": {"en": "Driving (balancing) moment", "sr": "Погонски (уравнотежавајући) момент", "ru": "Движущий (уравновешивающий) момент",
                       "bg": "Движещ (уравновесяващ) момент", "sl": "Pogonski (uravnotežni) moment"},
    "driving_force": {"en": "Driving (balancing) force", "sr": "Погонска (уравнотежавајућа) сила", "ru": "Движущая (уравновешивающая) сила",
                      "bg": "Движеща (уравновесяваща) сила", "sl": "Pogonska (uravnotežna) sila"},
    "no_mean_moment": {"en": "no mean: the mechanism does not assemble over the whole cycle",
                       "sr": "нема средње вредности: механизам се не склапа током целог циклуса",
                       "ru": "среднего нет: механизм не собирается на всём цикле",
                       "bg": "няма средна стойност: механизмът не се сглобява през целия цикъл",
                       "sl": "ni srednje vrednosti: mehanizem se ne sestavi v celem ciklu"},
    "no_mean_swing": {"en": "no mean: the input swings there and back, it does not turn",
                      "sr": "нема средње вредности: погонски члан се љуља тамо и назад, не окреће се",
                      "ru": "среднего нет: ведущее звено качается туда и обратно, а не вращается",
                      "bg": "няма средна стойност: водещото звено се люлее напред и назад, не се завърта",
                      "sl": "ni srednje vrednosti: pogonski člen niha tja in nazaj, ne vrti se"},
    "polar_diagram": {"en": "Polar diagram of the reaction", "sr": "Поларни дијаграм реакције", "ru": "Полярная диаграмма реакции",
                      "bg": "Полярна диаграма на реакцията", "sl": "Polarni diagram reakcije"},
    "frame_on_crank": {"en": "the frame on the crank", "sr": "постоље на кривају", "ru": "стойки на кривошип",
                       "bg": "стойката върху манивелата", "sl": "ogrodje na ročico"},
    "mean_value": {"en": "mean", "sr": "средња вредност", "ru": "среднее значение", "bg": "средна стойност", "sl": "srednja vrednost"},
    "pole": {"en": "pole", "sr": "пол", "ru": "полюс", "bg": "полюс", "sl": "pol"},
    "at_crank_angle": {"en": "at", "sr": "при", "ru": "при", "bg": "при", "sl": "pri"},
    "direction": {"en": "direction", "sr": "правац", "ru": "направление", "bg": "посока", "sl": "smer"},
    "polar_note": {"en": "Each vector from the pole is the reaction at one crank position; the numbers are the positions 0, 1, … from the output's extreme position.",
                   "sr": "Сваки вектор из пола је реакција у једном положају криваје; бројеви су положаји 0, 1, … од крајњег положаја излазног члана.",
                   "ru": "Каждый вектор из полюса — реакция в одном положении кривошипа; числа — положения 0, 1, … от крайнего положения выходного звена.",
                   "bg": "Всеки вектор от полюса е реакцията в едно положение на манивелата; числата са положенията 0, 1, … от крайното положение на изходното звено.",
                   "sl": "Vsak vektor iz pola je reakcija v eni legi ročice; številke so lege 0, 1, … od skrajne lege izhodnega člena."},
    # --- cycle law ---
    "driver_law": {"en": "driver law", "sr": "закон кретања погонског члана", "ru": "закон движения ведущего звена",
                   "bg": "закон на движение на водещото звено", "sl": "zakon gibanja pogonskega člena"},
    "law_constant": {"en": "constant speed", "sr": "константна брзина", "ru": "постоянная скорость",
                     "bg": "постоянна скорост", "sl": "konstantna hitrost"},
    "law_constant_angular": {"en": "constant angular velocity", "sr": "константна угаона брзина", "ru": "постоянная угловая скорость",
                             "bg": "постоянна ъглова скорост", "sl": "konstantna kotna hitrost"},
    "law_uniform": {"en": "uniformly accelerated", "sr": "равномерно убрзано", "ru": "равноускоренно",
                    "bg": "равноускорително", "sl": "enakomerno pospešeno"},
    "law_harmonic": {"en": "harmonic swing between", "sr": "хармонијско љуљање између", "ru": "гармоническое качание между",
                     "bg": "хармонично люлеене между", "sl": "harmonično nihanje med"},
    "equal_time_steps": {"en": "equal time steps", "sr": "једнаки временски кораци", "ru": "равные шаги по времени", "bg": "равни стъпки по време", "sl": "enaki časovni koraki"},
    "positive_along_guide": {"en": "positive along the guide's direction", "sr": "позитивно у смеру вођице", "ru": "положительно по направлению направляющей", "bg": "положително по посоката на водача", "sl": "pozitivno v smeri vodila"},
    "positive_ccw": {"en": "counter-clockwise positive", "sr": "позитивно супротно казаљки на сату", "ru": "положительно против часовой стрелки", "bg": "положително обратно на часовниковата стрелка", "sl": "pozitivno v nasprotni smeri urinega kazalca"},
    "from_position_0_extreme": {"en": "measured from position 0, an extreme position of the output link", "sr": "мери се од положаја 0, крајњег положаја излазног члана", "ru": "отсчитывается от положения 0, крайнего положения выходного звена", "bg": "измерва се от положение 0, крайно положение на изходното звено", "sl": "merjeno od lege 0, skrajne lege izhodnega člena"},
    "from_position_0": {"en": "measured from position 0", "sr": "мери се од положаја 0", "ru": "отсчитывается от положения 0", "bg": "измерва се от положение 0", "sl": "merjeno od lege 0"},
    "position_no": {"en": "No.", "sr": "Бр.", "ru": "№ п/п", "bg": "№ по ред", "sl": "Št."},
    "kd_extreme_reading": {"en": "at an extreme position ({v} = 0) the diagram does not give 0: each chord's mean velocity is plotted at its interval's middle, so at the extreme the curve through those points reads about the mean of the two neighbouring intervals' chords (of opposite sign), not the zero between them", "sr": "у крајњем положају ({v} = 0) дијаграм не даје 0: средња брзина сваке тетиве нанесена је у средини њеног интервала, па у крајњем положају крива кроз те тачке даје приближно средњу вредност тетива два суседна интервала (супротног знака), а не нулу између њих", "ru": "в крайнем положении ({v} = 0) диаграмма не даёт 0: средняя скорость каждой хорды отложена в середине её интервала, поэтому в крайнем положении кривая через эти точки даёт примерно среднее хорд двух соседних интервалов (разного знака), а не нуль между ними", "bg": "в крайно положение ({v} = 0) диаграмата не дава 0: средната скорост на всяка хорда е нанесена в средата на нейния интервал, затова в крайното положение кривата през тези точки дава приблизително средното на хордите на двата съседни интервала (с различен знак), а не нулата между тях", "sl": "v skrajni legi ({v} = 0) diagram ne da 0: srednja hitrost vsake tetive je nanesena v sredini njenega intervala, zato krivulja skozi te točke v skrajni legi da približno povprečje tetiv sosednjih intervalov (nasprotnega predznaka), ne ničle med njima"},
    "guide_position": {"en": "position on the guide", "sr": "положај на вођици", "ru": "положение на направляющей", "bg": "положение по водача", "sl": "lega na vodilu"},
    "scene_instant": {"en": "the scene's instant", "sr": "тренутак сцене", "ru": "момент сцены", "bg": "моментът на сцената",
                      "sl": "trenutek scene"},
    "law_at": {"en": "at", "sr": "при", "ru": "при", "bg": "при", "sl": "pri"},
    "law_at_limits": {"en": "at the limit positions", "sr": "у граничним положајима", "ru": "в крайних положениях",
                      "bg": "в крайните положения", "sl": "v mejnih legah"},
    "output_link": {"en": "output link", "sr": "излазни члан", "ru": "выходное звено", "bg": "изходно звено", "sl": "izhodni člen"},
    "stroke_H": {"en": "stroke", "sr": "ход", "ru": "ход", "bg": "ход", "sl": "hod"},
    "swing_psi": {"en": "swing", "sr": "угао љуљања", "ru": "угол качания", "bg": "ъгъл на люлеене", "sl": "kot nihanja"},
    "extreme_positions": {"en": "extreme positions", "sr": "крајњи положаји", "ru": "крайние положения",
                          "bg": "крайни положения", "sl": "skrajni legi"},
    "working_stroke": {"en": "working stroke", "sr": "радни ход", "ru": "рабочий ход", "bg": "работен ход", "sl": "delovni hod"},
    "time": {"en": "time", "sr": "време", "ru": "время", "bg": "време", "sl": "čas"},
    "four_bar_loop": {"en": "four-bar", "sr": "зглавкасти четвороугао", "ru": "шарнирный четырёхзвенник", "bg": "шарнирен четиризвенник",
                      "sl": "štirizgibni mehanizem"},
    "grashof_class": {"en": "Grashof class", "sr": "Грасхофова класа", "ru": "класс по Грасгофу", "bg": "клас по Грасхоф",
                      "sl": "Grashofov razred"},
    "crank-rocker": {"en": "crank-rocker", "sr": "кривајно-клацкајући", "ru": "кривошипно-коромысловый",
                     "bg": "колянно-кобиличен", "sl": "ročično-nihajni"},
    "double-crank": {"en": "double-crank", "sr": "двокривајни", "ru": "двухкривошипный", "bg": "двуколянов", "sl": "dvoročični"},
    "double-rocker": {"en": "double-rocker", "sr": "двоклацкајући", "ru": "двухкоромысловый", "bg": "двукобиличен",
                      "sl": "dvonihajni"},
    "change point": {"en": "change point", "sr": "гранични случај", "ru": "переходный случай",
                     "bg": "граничен случай", "sl": "mejni primer"},
    "triple-rocker": {"en": "triple-rocker (non-Grashof)", "sr": "троклацкајући (није Грасхофов)",
                      "ru": "трёхкоромысловый (не Грасгофов)", "bg": "трикобиличен (не е Грасхофов)", "sl": "trinihajni (ni Grashofov)"},
    "turn_fully": {"en": "turn fully", "sr": "окрећу се пуним кругом", "ru": "проворачиваются полностью",
                   "bg": "се завъртат изцяло", "sl": "se zavrtijo v celoti"},
    "none_turns": {"en": "no link turns fully", "sr": "ниједан члан се не окреће пуним кругом", "ru": "ни одно звено не проворачивается",
                   "bg": "никое звено не се завърта изцяло", "sl": "noben člen se ne zavrti v celoti"},
    # the centres table's column of lengths read off the drawing (P₁ⱼM for a point's v, the path's lengths for ω)
    "read_off_drawing": {"en": "from the drawing (lengths in mm)", "sr": "са цртежа (дужине у mm)", "ru": "по чертежу (длины в мм)",
                         "bg": "от чертежа (дължини в мм)", "sl": "z risbe (dolžine v mm)"},
    "law_given_instant_only": {"en": "the scene's {q} is not used: the cycle follows this law",
                               "sr": "задато {q} се не користи: циклус прати овај закон",
                               "ru": "заданное {q} не используется: цикл следует этому закону",
                               "bg": "зададеното {q} не се използва: цикълът следва този закон",
                               "sl": "podani {q} se ne uporablja: cikel sledi temu zakonu"},
    # --- the force pages set by Typst (plans.pages.forces) ---
    "image": {"en": "image", "sr": "слика", "ru": "изображение", "bg": "образ", "sl": "slika"},
    "lever_moments": {
        "en": "Moments about the pole p",
        "sr": "Моменти за пол p",
        "ru": "Моменты относительно полюса p",
        "bg": "Моменти спрямо полюса p",
        "sl": "Momenti okoli pola p",
    },
    "force_methods": {
        "en": "The three methods: analytic, force plans, Joukowski's lever (δ: the difference from the analytic value)",
        "sr": "Три методе: аналитички, планови сила, Жуковљева полуга (δ: разлика од аналитичке вредности)",
        "ru": "Три метода: аналитически, планы сил, рычаг Жуковского (δ: отличие от аналитического значения)",
        "bg": "Трите метода: аналитично, планове на силите, лост на Жуковски (δ: разлика от аналитичната стойност)",
        "sl": "Tri metode: analitično, načrti sil, Žukovskijev vzvod (δ: razlika od analitične vrednosti)",
    },
}


def check_language(lang: str) -> str:
    """*lang* if plans speaks it, else a ValueError naming the choices."""
    if lang not in LANGUAGES:
        raise ValueError(f"no language {lang!r}; plans speaks {', '.join(LANGUAGES)}")
    return lang


def term(key: str, lang: str = "en") -> str:
    """The words for *key* in *lang* (``"en"``, ``"sr"``, ``"ru"``, ``"bg"``, ``"sl"``)."""
    check_language(lang)
    return TERMS[key][lang]


# --- the solver's reasons and the assembly branches, in words ------------------------------
#
# The solvers and plans.structure write these in English (the CLI's stderr, the JSON); a page in
# another language says them in its own words.  Each English form is matched as a whole (its
# names, numbers and the position kept as they are) and written again from the language's
# template; a form not matched here is said by its group and its cause only, never in English.

_NAME = r"[^\s,:;()]+"

#: (pattern of the English form, language -> template), for the details after "at φ = …: "
_DETAILS: list[tuple[str, dict[str, str]]] = [  # the first that matches is used: the particular before the general
    (rf"\|(?P<be>{_NAME})\| = (?P<d>.+?) < the offset (?P<o>.+?) of the line from the pins \(gap (?P<gap>.+)\)$", {
        "sr": "|{be}| = {d} < одстојање праве од зглобова {o} (недостаје {gap})",
        "ru": "|{be}| = {d} < смещение прямой от шарниров {o} (не хватает {gap})",
        "bg": "|{be}| = {d} < отместването на правата от ставите {o} (не достигат {gap})",
        "sl": "|{be}| = {d} < odmik premice od zglobov {o} (manjka {gap})"}),
    (rf"(?P<rel>\|{_NAME}\| = .+? [<>] .+?) \(gap (?P<gap>.+)\)$", {
        "sr": "{rel} (недостаје {gap})", "ru": "{rel} (не хватает {gap})",
        "bg": "{rel} (не достигат {gap})", "sl": "{rel} (manjka {gap})"}),
    (rf"(?P<b>{_NAME}) and (?P<d>{_NAME}) coincide, or a point before them is not known$", {
        "sr": "{b} и {d} се поклапају или тачка пре њих није позната",
        "ru": "{b} и {d} совпадают, или предшествующая им точка не известна",
        "bg": "{b} и {d} съвпадат или предхождаща ги точка не е известна",
        "sl": "{b} in {d} sovpadata ali točka pred njima ni znana"}),
    (rf"the line (?P<c>{_NAME}) runs on \(parallel to (?P<key>{_NAME})\) passes (?P<y>.+?) from (?P<b>{_NAME}), "
     rf"farther than (?P<bc>{_NAME}) = (?P<l>.+?) \(gap (?P<gap>.+)\)$", {
        "sr": "права по којој се креће {c} (паралелна са {key}) пролази на {y} од {b}, даље од {bc} = {l} (недостаје {gap})",
        "ru": "прямая, по которой движется {c} (параллельная {key}), проходит в {y} от {b}, дальше, чем {bc} = {l} (не хватает {gap})",
        "bg": "правата, по която се движи {c} (успоредна на {key}), минава на {y} от {b}, по-далеч от {bc} = {l} (не достигат {gap})",
        "sl": "premica, po kateri se giblje {c} (vzporedna s {key}), poteka {y} od {b}, dlje od {bc} = {l} (manjka {gap})"}),
    (rf"a point before (?P<b>{_NAME}) or the guide (?P<key>{_NAME}) is not known$", {
        "sr": "тачка пре {b} или вођица {key} није позната",
        "ru": "предшествующая {b} точка или направляющая {key} не известна",
        "bg": "предхождаща {b} точка или водачът {key} не е известен",
        "sl": "točka pred {b} ali vodilo {key} ni znano"}),
    (rf"(?P<b>{_NAME}) and (?P<e>{_NAME}) coincide: the line has no direction$", {
        "sr": "{b} и {e} се поклапају: права нема правац", "ru": "{b} и {e} совпадают: направление прямой не определено",
        "bg": "{b} и {e} съвпадат: правата няма посока", "sl": "{b} in {e} sovpadata: premica nima smeri"}),
    (rf"a point before (?P<b>{_NAME}) or (?P<e>{_NAME}) is not known$", {
        "sr": "тачка пре {b} или {e} није позната", "ru": "предшествующая {b} или {e} точка не известна",
        "bg": "предхождаща {b} или {e} точка не е известна", "sl": "točka pred {b} ali {e} ni znana"}),
    # what is in line at a dead centre
    (rf"(?P<b>{_NAME}), (?P<c>{_NAME}) and (?P<d>{_NAME}) are in line$", {
        "sr": "{b}, {c} и {d} су на истој правој", "ru": "{b}, {c} и {d} лежат на одной прямой",
        "bg": "{b}, {c} и {d} лежат на една права", "sl": "{b}, {c} in {d} ležijo na isti premici"}),
    (rf"(?P<bc>{_NAME}) is perpendicular to the guide (?P<key>{_NAME})$", {
        "sr": "{bc} је управна на вођицу {key}", "ru": "{bc} перпендикулярна направляющей {key}",
        "bg": "{bc} е перпендикулярна на водача {key}", "sl": "{bc} je pravokotna na vodilo {key}"}),
    (rf"the line (?P<key>{_NAME}) is perpendicular to (?P<be>{_NAME})$", {
        "sr": "права {key} је управна на {be}", "ru": "прямая {key} перпендикулярна {be}",
        "bg": "правата {key} е перпендикулярна на {be}", "sl": "premica {key} je pravokotna na {be}"}),
    (rf"the guides (?P<k1>{_NAME}) and (?P<k2>{_NAME}) are parallel: (?P<c>{_NAME}) has no definite position$", {
        "sr": "вођице {k1} и {k2} су паралелне: {c} нема одређен положај",
        "ru": "направляющие {k1} и {k2} параллельны: положение {c} не определено",
        "bg": "водачите {k1} и {k2} са успоредни: {c} няма определено положение",
        "sl": "vodili {k1} in {k2} sta vzporedni: {c} nima določene lege"}),
    (rf"the lines (?P<k1>{_NAME}) and (?P<k2>{_NAME}) are parallel: the position is not definite$", {
        "sr": "праве {k1} и {k2} су паралелне: положај није одређен",
        "ru": "прямые {k1} и {k2} параллельны: положение не определено",
        "bg": "правите {k1} и {k2} са успоредни: положението не е определено",
        "sl": "premici {k1} in {k2} sta vzporedni: lega ni določena"}),
]

#: (pattern of a whole reason, language -> template); {detail} is said again by _DETAILS
_REASONS: list[tuple[str, dict[str, str]]] = [
    (rf"(?P<g>[^:]+?): joint (?P<c>{_NAME}) cannot assemble at (?P<w>[^:]+): (?P<detail>.+)$", {
        "sr": "{g}: зглоб {c} се не може саставити при {w}: {detail}",
        "ru": "{g}: шарнир {c} не собирается при {w}: {detail}",
        "bg": "{g}: ставата {c} не може да се сглоби при {w}: {detail}",
        "sl": "{g}: zgloba {c} ni mogoče sestaviti pri {w}: {detail}"}),
    (rf"(?P<g>[^:]+?): the line (?P<key>{_NAME}) cannot pass through (?P<e>{_NAME}) at (?P<w>[^:]+): (?P<detail>.+)$", {
        "sr": "{g}: права {key} не може проћи кроз {e} при {w}: {detail}",
        "ru": "{g}: прямая {key} не может пройти через {e} при {w}: {detail}",
        "bg": "{g}: правата {key} не може да мине през {e} при {w}: {detail}",
        "sl": "{g}: premica {key} ne more potekati skozi {e} pri {w}: {detail}"}),
    (rf"(?P<g>[^:]+?): dead centre at (?P<w>[^:]+): (?P<detail>.+?)"
     r"(?: \(\|sin\| of the angle between the construction lines = (?P<s>\S+), below the dead-centre threshold (?P<t>[^)]+)\))?"
     rf"; the 2×2 velocity system of links (?P<i>{_NAME}) and (?P<j>{_NAME}) is singular and their velocities do not exist there$", {
        "sr": "{g}: мртви положај при {w}: {detail}{sine}; систем 2×2 за брзине чланова {i} и {j} је сингуларан и њихове брзине ту не постоје",
        "ru": "{g}: мёртвое положение при {w}: {detail}{sine}; система 2×2 для скоростей звеньев {i} и {j} вырождена, их скорости здесь не существуют",
        "bg": "{g}: мъртво положение при {w}: {detail}{sine}; системата 2×2 за скоростите на звената {i} и {j} е сингулярна и скоростите им тук не съществуват",
        "sl": "{g}: mrtva lega pri {w}: {detail}{sine}; sistem 2×2 za hitrosti členov {i} in {j} je singularen in njune hitrosti tu ne obstajajo"}),
]

_SINE = {
    "sr": " (|sin| угла између конструкционих правих = {s}, испод прага мртвог положаја {t})",
    "ru": " (|sin| угла между прямыми построения = {s}, ниже порога мёртвого положения {t})",
    "bg": " (|sin| на ъгъла между построителните прави = {s}, под прага на мъртво положение {t})",
    "sl": " (|sin| kota med konstrukcijskima premicama = {s}, pod pragom mrtve lege {t})",
}

_MORE = re.compile(r" \(and at \d+ more of the positions asked for; allow_partial=True returns NaN there\)")


def _detail(text: str, lang: str) -> str | None:
    for pattern, words in _DETAILS:
        m = re.fullmatch(pattern, text)
        if m:
            return words[lang].format(**m.groupdict())
    return None


def reason_text(message: str, lang: str = "en", cause: str = "no_assembly") -> str:
    """Why a position is not solved, in *lang*: the solver's English *message* said again in its words.

    Names, numbers and the position (``φ₂ = 60.0°``) stay as they are.  A
    message of a form not known here is said by its group and *cause*
    (``"no_assembly"`` or ``"dead_centre"``, see :data:`TERMS`), never in English.

    >>> reason_text("RRR(3,4): joint B cannot assemble at φ = 60.0°: |AD| = 0.656 m > AB + BD = 0.650 m (gap 0.006 m)", "ru")
    'RRR(3,4): шарнир B не собирается при φ = 60.0°: |AD| = 0.656 m > AB + BD = 0.650 m (не хватает 0.006 m)'
    """
    check_language(lang)
    if lang == "en":
        return message
    text = _MORE.sub("", message.strip())
    for pattern, words in _REASONS:
        m = re.fullmatch(pattern, text)
        if not m:
            continue
        fields = m.groupdict()
        detail = _detail(fields.pop("detail"), lang)
        if detail is None:
            break
        s, t = fields.pop("s", None), fields.pop("t", None)
        sine = _SINE[lang].format(s=s, t=t) if s is not None else ""
        return words[lang].format(detail=detail, sine=sine, **fields)
    group = re.match(r"^\s*([A-Z]{3}\([^)]*\))", text)
    return (f"{group.group(1)}: " if group else "") + term(cause, lang)


#: the three forms of plans.structure.Branch.words, language -> template
_BRANCHES: list[tuple[str, dict[str, str]]] = [
    (rf"(?P<c>{_NAME}) to the left of (?P<b>{_NAME})→(?P<d>{_NAME})$", {
        "sr": "{c} лево од {b}→{d}", "ru": "{c} слева от {b}→{d}", "bg": "{c} вляво от {b}→{d}", "sl": "{c} levo od {b}→{d}"}),
    (rf"(?P<c>{_NAME}) to the right of (?P<b>{_NAME})→(?P<d>{_NAME})$", {
        "sr": "{c} десно од {b}→{d}", "ru": "{c} справа от {b}→{d}", "bg": "{c} вдясно от {b}→{d}", "sl": "{c} desno od {b}→{d}"}),
    (rf"(?P<c>{_NAME}) at the intersection further along (?P<key>{_NAME}) \(of the two the circle about (?P<b>{_NAME}) meets\)$", {
        "sr": "{c} у пресеку даље дуж {key} (од два у којима је сече круг око {b})",
        "ru": "{c} в точке пересечения дальше вдоль {key} (из двух, где её пересекает окружность с центром {b})",
        "bg": "{c} в пресечната точка по-нататък по {key} (от двете, в които я пресича окръжността около {b})",
        "sl": "{c} v presečišču dlje vzdolž {key} (od dveh, v katerih jo seka krožnica okoli {b})"}),
    (rf"(?P<c>{_NAME}) at the intersection nearer the start of (?P<key>{_NAME}) \(of the two the circle about (?P<b>{_NAME}) meets\)$", {
        "sr": "{c} у пресеку ближе почетку {key} (од два у којима је сече круг око {b})",
        "ru": "{c} в точке пересечения ближе к началу {key} (из двух, где её пересекает окружность с центром {b})",
        "bg": "{c} в пресечната точка по-близо до началото на {key} (от двете, в които я пресича окръжността около {b})",
        "sl": "{c} v presečišču bliže začetku {key} (od dveh, v katerih jo seka krožnica okoli {b})"}),
    (rf"line (?P<key>{_NAME}) pointing from (?P<a>{_NAME}) towards (?P<b>{_NAME})$", {
        "sr": "права {key} усмерена од {a} ка {b}", "ru": "прямая {key} направлена от {a} к {b}",
        "bg": "правата {key} е насочена от {a} към {b}", "sl": "premica {key} usmerjena od {a} proti {b}"}),
]


def branch_text(words: str, lang: str = "en") -> str | None:
    """An assembly branch in *lang*: ``"C to the left of B→D"`` → ``"C слева от B→D"``; None for a form not known here."""
    check_language(lang)
    if lang == "en":
        return words
    for pattern, templates in _BRANCHES:
        m = re.fullmatch(pattern, words.strip())
        if m:
            return templates[lang].format(**m.groupdict())
    return None


# the kinematic diagrams' page (issue 20): a rate constant over the cycle said instead of drawn
TERMS.update({
    "kd_zero": {
        "en": "{q} = 0 over the whole cycle (its diagram is the t axis itself and is not drawn)",
        "sr": "{q} = 0 током целог циклуса (дијаграм се поклапа са осом t и није цртан)",
        "ru": "{q} = 0 на всём цикле (диаграмма совпадает с осью t и не строится)",
        "bg": "{q} = 0 през целия цикъл (диаграмата съвпада с оста t и не е построена)",
        "sl": "{q} = 0 v celem ciklu (diagram sovpada z osjo t in ni narisan)",
    },
    "kd_constant": {
        "en": "{q} = {value} {unit}, constant over the whole cycle (its diagram, a line parallel to the t axis, is not drawn)",
        "sr": "{q} = {value} {unit}, константно током целог циклуса (дијаграм, права паралелна оси t, није цртан)",
        "ru": "{q} = {value} {unit}, постоянна на всём цикле (диаграмма, прямая, параллельная оси t, не строится)",
        "bg": "{q} = {value} {unit}, постоянна през целия цикъл (диаграмата, права, успоредна на оста t, не е построена)",
        "sl": "{q} = {value} {unit}, konstantna v celem ciklu (diagram, premica, vzporedna osi t, ni narisan)",
    },
    "signed_elsewhere": {
        "en": "{points}: the output slider; its signed v and a are in the kinematic diagrams",
        "sr": "{points}: излазни клизач; његове v и a са знаком су у кинематским дијаграмима",
        "ru": "{points}: выходной ползун; его v и a со знаком — в кинематических диаграммах",
        "bg": "{points}: изходният плъзгач; v и a със знак са в кинематичните диаграми",
        "sl": "{points}: izhodni drsnik; njegova v in a s predznakom sta v kinematičnih diagramih",
    },
})


# --- plan notes and readings (issue 20 §3, branch plan-notes) -------------------------------------
TERMS.update({
    # a plan's enlarged detail, named as a drawing names it ("detail I"; ГОСТ 2.305: "выносной элемент I")
    # a proportion's result where the plan, drawn exactly, measures another last digit (its inputs rounded to 0.1 mm)
    "on_the_plan": {"en": "on the plan", "sr": "на плану", "ru": "на плане", "bg": "на плана", "sl": "na načrtu"},
    "detail": {
        "en": "detail",
        "sr": "детаљ",
        "ru": "выносной элемент",
        "bg": "детайл",
        "sl": "detajl",
    },
    # a sliding driver's cycle is its one-way stroke (issue 20, second review): "one stroke", not "one cycle"
    "stroke_time": {"en": "time of the stroke", "sr": "време хода", "ru": "время хода", "bg": "време на хода", "sl": "čas hoda"},
    "stroke_diagrams": {"en": "Kinematic diagrams over one stroke", "sr": "Кинематски дијаграми током једног хода",
                        "ru": "Кинематические диаграммы за один ход", "bg": "Кинематични диаграми за един ход",
                        "sl": "Kinematični diagrami v enem hodu"},
    # the key of a plan's notes on vectors that lie one along another (their angles)
    "angle_from_x": {"en": "∠ in the notes: from the x axis, counter-clockwise", "sr": "∠ у напоменама: од осе x, супротно од казаљке на сату",
                     "ru": "∠ в примечаниях: от оси x, против часовой стрелки", "bg": "∠ в бележките: от оста x, обратно на часовниковата стрелка",
                     "sl": "∠ v opombah: od osi x, v nasprotni smeri urnega kazalca"},
    # the plan of positions: the marks whose number found no room of its own
    "not_numbered": {"en": "not numbered (no room beside the point)", "sr": "без броја (нема места поред тачке)",
                     "ru": "без номера (нет места рядом с точкой)", "bg": "без номер (няма място до точката)",
                     "sl": "brez številke (ni prostora ob točki)"},
})


# --- the kinematic diagrams' table against the plate's plans (issue 20, review round 2, branch r2-kinematic) --------
TERMS.update({
    "kd_plans_signs": {
        "en": "{plan}: read on this plate's plans of that position (their k_v, k_a, to their drafting precision, as in their readings), "
              "the magnitude with the sign of the sense drawn; {v} and {a} signed: {sense}",
        "sr": "{plan}: очитано на плановима тог положаја у овом раду (њихови k_v, k_a, с тачношћу цртања, као у очитавањима), "
              "интензитет са знаком нацртаног смера; {v} и {a} са знаком: {sense}",
        "ru": "{plan}: снято с планов этого положения в данной работе (их k_v, k_a, с точностью построения, как в отсчётах), "
              "величина со знаком построенного направления; {v} и {a} со знаком: {sense}",
        "bg": "{plan}: отчетено от плановете на това положение в тази разработка (техните k_v, k_a, с точността на чертане, както в отчитанията), "
              "големината със знака на начертаната посока; {v} и {a} със знак: {sense}",
        "sl": "{plan}: odčitano z načrtov te lege v tem izdelku (njihova k_v, k_a, z natančnostjo risanja, kot v odčitkih), "
              "velikost s predznakom narisane smeri; {v} in {a} s predznakom: {sense}",
    },
    "kd_no_plan": {
        "en": "—: this plate draws no plan of that position (the diagrams have positions the plans do not)",
        "sr": "—: у овом раду нема плана тог положаја (дијаграми имају положаје којих нема међу плановима)",
        "ru": "—: в данной работе нет плана этого положения (в диаграммах есть положения, которых нет среди планов)",
        "bg": "—: в тази разработка няма план на това положение (диаграмите имат положения, които ги няма сред плановете)",
        "sl": "—: v tem izdelku ni načrta te lege (diagrami imajo lege, ki jih med načrti ni)",
    },
    "kd_no_acceleration_plan": {
        "en": "{a} plan —: the acceleration plan of that position is not drawn on this plate (drawn for positions {positions})",
        "sr": "{a} план —: план убрзања тог положаја није нацртан у овом раду (нацртан за положаје {positions})",
        "ru": "{a} план —: план ускорений этого положения в данной работе не построен (построен для положений {positions})",
        "bg": "{a} план —: планът на ускоренията на това положение не е начертан в тази разработка (начертан за положения {positions})",
        "sl": "{a} načrt —: načrt pospeškov te lege v tem izdelku ni narisan (narisan za lege {positions})",
    },
    "kd_analytic_cut": {
        "en": "▲, ▼ on a frame's edge: the dashed analytic curve leaves the frame there and is cut (the frame is sized to the chords' construction)",
        "sr": "▲, ▼ на ивици оквира: испрекидана аналитичка крива ту излази из оквира и прекинута је (оквир је мерен према конструкцији тетива)",
        "ru": "▲, ▼ на краю рамки: штриховая аналитическая кривая там выходит за рамку и обрезана (рамка рассчитана на построение хорд)",
        "bg": "▲, ▼ на ръба на рамката: прекъснатата аналитична крива там излиза от рамката и е отрязана (рамката е оразмерена по построението с хорди)",
        "sl": "▲, ▼ na robu okvira: črtkana analitična krivulja tam zapusti okvir in je odrezana (okvir je določen po konstrukciji tetiv)",
    },
    "kd_peak_note": {
        "en": "at {n} positions the chords flatten the fastest part of the cycle: at position {position} the {q}–t diagram gives {diagram} {unit} "
              "against {analytic} {unit} analytic (δ {error} %); draw more positions there (e.g. {more}) for a smaller error",
        "sr": "при {n} положаја тетиве заравњују најбржи део циклуса: у положају {position} дијаграм {q}–t даје {diagram} {unit} "
              "према {analytic} {unit} аналитички (δ {error} %); за мању грешку нацртајте више положаја (нпр. {more})",
        "ru": "при {n} положениях хорды сглаживают самую быструю часть цикла: в положении {position} диаграмма {q}–t даёт {diagram} {unit} "
              "против {analytic} {unit} аналитически (δ {error} %); для меньшей погрешности возьмите больше положений (напр. {more})",
        "bg": "при {n} положения хордите заглаждат най-бързата част от цикъла: в положение {position} диаграмата {q}–t дава {diagram} {unit} "
              "срещу {analytic} {unit} аналитично (δ {error} %); за по-малка грешка начертайте повече положения (напр. {more})",
        "sl": "pri {n} legah tetive zgladijo najhitrejši del cikla: v legi {position} diagram {q}–t da {diagram} {unit} "
              "proti {analytic} {unit} analitično (δ {error} %); za manjšo napako narišite več leg (npr. {more})",
    },
})


# --- the force pages' input data (issue 22 review, branch r2-forces) ---------------------------------------
TERMS.update({
    "force_data": {
        "en": "Data for the force analysis",
        "sr": "Полазни подаци за кинетостатичку анализу",
        "ru": "Исходные данные для силового расчёта",
        "bg": "Изходни данни за силовия анализ",
        "sl": "Vhodni podatki za kinetostatično analizo",
    },
    "mass_centre": {"en": "centre of mass S", "sr": "тежиште S", "ru": "центр масс S", "bg": "масов център S", "sl": "težišče S"},
    # the offset of a slider-crank's guide from the crank's pivot (Russian, Bulgarian: дезаксиал e)
    "offset_e": {"en": "offset", "sr": "ексцентрицитет", "ru": "дезаксаж", "bg": "дезаксаж", "sl": "izmik"},
    "gravity_g": {
        "en": "gravity",
        "sr": "убрзање Земљине теже",
        "ru": "ускорение свободного падения",
        "bg": "земно ускорение",
        "sl": "težni pospešek",
    },
    "downwards": {"en": "downwards", "sr": "наниже", "ru": "вниз", "bg": "надолу", "sl": "navzdol"},
    "load_at": {
        "en": "at {point} of link {link}",
        "sr": "у тачки {point} члана {link}",
        "ru": "в точке {point} звена {link}",
        "bg": "в точка {point} на звено {link}",
        "sl": "v točki {point} člena {link}",
    },
    "on_link": {"en": "on link {link}", "sr": "на члану {link}", "ru": "на звене {link}", "bg": "на звено {link}", "sl": "na členu {link}"},
    "against_velocity": {
        "en": "against the velocity of {point}",
        "sr": "супротно брзини тачке {point}",
        "ru": "против скорости точки {point}",
        "bg": "срещу скоростта на точка {point}",
        "sl": "nasproti hitrosti točke {point}",
    },
    "working_only": {
        "en": "over the working stroke only",
        "sr": "само током радног хода",
        "ru": "только на рабочем ходу",
        "bg": "само при работния ход",
        "sl": "samo med delovnim gibom",
    },
})


# --- the A3 sheets (issue 20, sheets review) ---------------------------------------------------------
TERMS.update({
    # a line under the plans' legend on a sheet: what the notes under a plan are
    "plan_notes_legend": {
        "en": "Short segments and near-coincident directions are given under the plan (lengths in mm on the plan, "
              "angles from the x axis, counter-clockwise).",
        "sr": "Кратке дужи и правци који се скоро поклапају дати су испод плана (дужине у mm на плану, "
              "углови од осе x, супротно од казаљке на сату).",
        "ru": "Короткие отрезки и почти совпадающие направления указаны под планом (длины в мм на плане, "
              "углы от оси x, против часовой стрелки).",
        "bg": "Късите отсечки и почти съвпадащите направления са дадени под плана (дължини в mm на плана, "
              "ъгли от оста x, обратно на часовниковата стрелка).",
        "sl": "Kratke daljice in skoraj sovpadajoče smeri so podane pod načrtom (dolžine v mm na načrtu, "
              "koti od osi x, v nasprotni smeri urinega kazalca).",
    },
})
