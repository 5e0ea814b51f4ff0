// GSL reports errors through return codes here, never through its default handler (which
// aborts). The handler is process-wide, so it is switched off once, safely from any thread.
#pragma once

#include <gsl/gsl_errno.h>

namespace trebuchet {

inline void use_gsl_return_codes() {
  static const bool switched_off = (gsl_set_error_handler_off(), true);  // thread-safe one-time initialisation
  (void)switched_off;
}

}  // namespace trebuchet
