// Everything a generated rule-file translation unit needs.
#pragma once

#include <acanthus/body.hpp>
#include <acanthus/canvas.hpp>
#include <acanthus/element.hpp>
#include <acanthus/param.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/pattern_tables.hpp>
#include <acanthus/point.hpp>
#include <acanthus/program.hpp>
#include <acanthus/proxy.hpp>
#include <acanthus/rule_call.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <cmath>
#include <string>
#include <vector>
