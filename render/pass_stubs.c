/* temporary: weak stand-ins until every pass file exists */
#include "rd.h"
__attribute__((weak)) int rd_pass_grid(rd_run *run) {
  (void)run;
  return 0;
}
__attribute__((weak)) int rd_pass_area(rd_run *run) {
  (void)run;
  return 0;
}
__attribute__((weak)) int rd_pass_hvl(rd_run *run) {
  (void)run;
  return 0;
}
__attribute__((weak)) int rd_pass_ssf(rd_run *run) {
  (void)run;
  return 0;
}
