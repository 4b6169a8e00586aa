// The filters plugin: stages that clean up depth images before geometry is computed from them.
#include "facet/plugin.hpp"

#include "filter/median_filter.hpp"

FACET_PLUGIN("facet_filters", "0.1.0") {
  registrar.add<facet::filters::MedianFilter>();
}
