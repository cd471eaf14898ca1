// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
/* Proof that libOSMesa leaks by itself (Testing/Sanitizers/lsan.supp): a 3.2 core context made
   current on a 1x1 buffer, released and destroyed, as the osmesa back end does. Mesa 22.3.6
   (Debian 12) never frees the buffer OSMesaMakeCurrent creates; LeakSanitizer reports 480 bytes
   in 5 allocations, all from libOSMesa.so.8 (direct: +0xb81de; indirect: +0x429ad0 and
   OSMesaMakeCurrent), the same as in the tests.
     gcc -fsanitize=address Testing/Sanitizers/osmesa-leak.c -lOSMesa -o /tmp/osmesa-leak
     /tmp/osmesa-leak */
#include <GL/osmesa.h>
#include <stdio.h>

int main(void)
{
  const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS,
    0, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
    OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  unsigned char buffer[4];
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, NULL);
  if (!context || !OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, 1, 1))
  {
    puts("no OSMesa context");
    return 1;
  }
  OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
  OSMesaDestroyContext(context);
  puts("context created, made current, released and destroyed");
  return 0;
}
