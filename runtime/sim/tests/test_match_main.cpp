// kse-match with the simulator's test behaviours (test_behaviours.h), among them those that
// throw, hang and crash: the process tests (match_process_test.cpp) play it.
#include "test_behaviours.h"
