// Sanitizer settings compiled into every executable of a TABLETOP_SANITIZE
// build, so `ctest` needs no environment: any report fails the test that
// caused it, leaks included. The suppressions name libraries outside
// tabletop that keep allocations alive until exit by design (the X
// client, GLUT, Mesa's drivers); tabletop's own code is never suppressed.
//
// intercept_tls_get_addr=0: up to GCC 13 (LLVM 16) the runtime's
// __tls_get_addr interceptor takes a dynamic TLS block that happens to
// start sizeof(Glibc_2_19_tls_header) bytes past a page boundary for a
// pre-2.25 glibc block and reads a size from before it; LeakSanitizer's
// tracer then dies at exit ("Tracer caught signal 11") after the test has
// passed. Mesa's drivers use dynamic TLS, so render tests hit it whenever
// the layout lines up (one did every time, with a longer command line).

extern "C" {

const char* __asan_default_options() { return "detect_leaks=1:abort_on_error=0:halt_on_error=1:intercept_tls_get_addr=0"; }

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

const char* __lsan_default_options() { return "print_suppressions=0"; }

const char* __lsan_default_suppressions() {
  return "leak:libX11.so\n"
         "leak:libxcb.so\n"
         "leak:libglut.so\n"
         "leak:libGLX_mesa.so\n"
         "leak:libGLX.so\n"
         "leak:libGL.so\n"
         "leak:libOSMesa.so\n"
         "leak:libgallium\n"
         "leak:swrast_dri.so\n"
         "leak:libLLVM\n";
}

}  // extern "C"
