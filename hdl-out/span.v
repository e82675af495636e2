

module span(clock,width,inp$valid,inp$ready,inp$y,inp$xl,inp$xr,inp$left_z,inp$left_c0,inp$left_c1,inp$left_c2,inp$right_z,inp$right_c0,inp$right_c1,inp$right_c2,inp$ddx_z,inp$ddx_c0,inp$ddx_c1,inp$ddx_c2,out$valid,out$ready,out$x,out$y,out$z,out$rgb0,out$rgb1,out$rgb2,idle);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$y;
    input wire  [12:0] inp$xl;
    input wire  [12:0] inp$xr;
    input wire  [35:0] inp$left_z;
    input wire  [31:0] inp$left_c0;
    input wire  [31:0] inp$left_c1;
    input wire  [31:0] inp$left_c2;
    input wire  [35:0] inp$right_z;
    input wire  [31:0] inp$right_c0;
    input wire  [31:0] inp$right_c1;
    input wire  [31:0] inp$right_c2;
    input wire  [39:0] inp$ddx_z;
    input wire  [35:0] inp$ddx_c0;
    input wire  [35:0] inp$ddx_c1;
    input wire  [35:0] inp$ddx_c2;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [9:0] out$x;
    output reg  [9:0] out$y;
    output reg  [15:0] out$z;
    output reg  [7:0] out$rgb0;
    output reg  [7:0] out$rgb1;
    output reg  [7:0] out$rgb2;
    output reg  idle;
    
    // Stub signals
    wire  clip_x$on;
    wire  clip_z$on;
    reg  busy$d;
    wire  busy$q;
    reg  busy$clock;
    reg  drop$d;
    wire  drop$q;
    reg  drop$clock;
    reg  left$d;
    wire  left$q;
    reg  left$clock;
    reg  [12:0] x$d;
    wire  [12:0] x$q;
    reg  x$clock;
    reg  [12:0] last$d;
    wire  [12:0] last$q;
    reg  last$clock;
    reg  at_last$d;
    wire  at_last$q;
    reg  at_last$clock;
    reg  [9:0] y$d;
    wire  [9:0] y$q;
    reg  y$clock;
    reg  [35:0] a_z$d;
    wire  [35:0] a_z$q;
    reg  a_z$clock;
    reg  [31:0] a_c0$d;
    wire  [31:0] a_c0$q;
    reg  a_c0$clock;
    reg  [31:0] a_c1$d;
    wire  [31:0] a_c1$q;
    reg  a_c1$clock;
    reg  [31:0] a_c2$d;
    wire  [31:0] a_c2$q;
    reg  a_c2$clock;
    reg  [35:0] d_z$d;
    wire  [35:0] d_z$q;
    reg  d_z$clock;
    reg  [31:0] d_c0$d;
    wire  [31:0] d_c0$q;
    reg  d_c0$clock;
    reg  [31:0] d_c1$d;
    wire  [31:0] d_c1$q;
    reg  d_c1$clock;
    reg  [31:0] d_c2$d;
    wire  [31:0] d_c2$q;
    reg  d_c2$clock;
    reg  [35:0] zl$x;
    wire  zl$neg;
    wire  zl$over;
    reg  [35:0] zr$x;
    wire  zr$neg;
    wire  zr$over;
    reg  [12:0] xl_neg$x;
    wire  xl_neg$neg;
    reg  [12:0] xr_neg$x;
    wire  xr_neg$neg;
    reg  [35:0] zp$x;
    wire  zp$neg;
    wire  zp$over;
    wire  [15:0] zp$low;
    reg  [31:0] c0$x;
    wire  c0$neg;
    wire  c0$over;
    wire  [7:0] c0$low;
    reg  [31:0] c1$x;
    wire  c1$neg;
    wire  c1$over;
    wire  [7:0] c1$low;
    reg  [31:0] c2$x;
    wire  c2$neg;
    wire  c2$over;
    wire  [7:0] c2$low;
    reg  [12:0] xl_on$a;
    reg  [12:0] xl_on$b;
    wire  xl_on$lt;
    reg  o_valid$d;
    wire  o_valid$q;
    reg  o_valid$clock;
    reg  [9:0] o_x$d;
    wire  [9:0] o_x$q;
    reg  o_x$clock;
    reg  [9:0] o_y$d;
    wire  [9:0] o_y$q;
    reg  o_y$clock;
    reg  [15:0] o_z$d;
    wire  [15:0] o_z$q;
    reg  o_z$clock;
    reg  [7:0] o_rgb0$d;
    wire  [7:0] o_rgb0$q;
    reg  o_rgb0$clock;
    reg  [7:0] o_rgb1$d;
    wire  [7:0] o_rgb1$q;
    reg  o_rgb1$clock;
    reg  [7:0] o_rgb2$d;
    wire  [7:0] o_rgb2$q;
    reg  o_rgb2$clock;
    
    // Local signals
    reg  [12:0] x_next;
    reg  [12:0] x_first;
    reg  [12:0] x_last;
    reg  one_pixel;
    reg  xr_off;
    reg  [12:0] last_column;
    reg  dropped;
    reg  ends;
    reg  [12:0] width_x;
    reg  valid;
    reg  [7:0] rgb0;
    reg  [7:0] rgb1;
    reg  [7:0] rgb2;
    reg  advance;
    reg  ready;
    reg  accept;
    
    // Sub module instances
    span$clip_x clip_x(
        .on(clip_x$on)
    );
    span$clip_z clip_z(
        .on(clip_z$on)
    );
    span$busy busy(
        .d(busy$d),
        .q(busy$q),
        .clock(busy$clock)
    );
    span$drop drop(
        .d(drop$d),
        .q(drop$q),
        .clock(drop$clock)
    );
    span$left left(
        .d(left$d),
        .q(left$q),
        .clock(left$clock)
    );
    span$x x(
        .d(x$d),
        .q(x$q),
        .clock(x$clock)
    );
    span$last last(
        .d(last$d),
        .q(last$q),
        .clock(last$clock)
    );
    span$at_last at_last(
        .d(at_last$d),
        .q(at_last$q),
        .clock(at_last$clock)
    );
    span$y y(
        .d(y$d),
        .q(y$q),
        .clock(y$clock)
    );
    span$a_z a_z(
        .d(a_z$d),
        .q(a_z$q),
        .clock(a_z$clock)
    );
    span$a_c0 a_c0(
        .d(a_c0$d),
        .q(a_c0$q),
        .clock(a_c0$clock)
    );
    span$a_c1 a_c1(
        .d(a_c1$d),
        .q(a_c1$q),
        .clock(a_c1$clock)
    );
    span$a_c2 a_c2(
        .d(a_c2$d),
        .q(a_c2$q),
        .clock(a_c2$clock)
    );
    span$d_z d_z(
        .d(d_z$d),
        .q(d_z$q),
        .clock(d_z$clock)
    );
    span$d_c0 d_c0(
        .d(d_c0$d),
        .q(d_c0$q),
        .clock(d_c0$clock)
    );
    span$d_c1 d_c1(
        .d(d_c1$d),
        .q(d_c1$q),
        .clock(d_c1$clock)
    );
    span$d_c2 d_c2(
        .d(d_c2$d),
        .q(d_c2$q),
        .clock(d_c2$clock)
    );
    span$zl zl(
        .x(zl$x),
        .neg(zl$neg),
        .over(zl$over)
    );
    span$zr zr(
        .x(zr$x),
        .neg(zr$neg),
        .over(zr$over)
    );
    span$xl_neg xl_neg(
        .x(xl_neg$x),
        .neg(xl_neg$neg)
    );
    span$xr_neg xr_neg(
        .x(xr_neg$x),
        .neg(xr_neg$neg)
    );
    span$zp zp(
        .x(zp$x),
        .neg(zp$neg),
        .over(zp$over),
        .low(zp$low)
    );
    span$c0 c0(
        .x(c0$x),
        .neg(c0$neg),
        .over(c0$over),
        .low(c0$low)
    );
    span$c1 c1(
        .x(c1$x),
        .neg(c1$neg),
        .over(c1$over),
        .low(c1$low)
    );
    span$c2 c2(
        .x(c2$x),
        .neg(c2$neg),
        .over(c2$over),
        .low(c2$low)
    );
    span$xl_on xl_on(
        .a(xl_on$a),
        .b(xl_on$b),
        .lt(xl_on$lt)
    );
    span$o_valid o_valid(
        .d(o_valid$d),
        .q(o_valid$q),
        .clock(o_valid$clock)
    );
    span$o_x o_x(
        .d(o_x$d),
        .q(o_x$q),
        .clock(o_x$clock)
    );
    span$o_y o_y(
        .d(o_y$d),
        .q(o_y$q),
        .clock(o_y$clock)
    );
    span$o_z o_z(
        .d(o_z$d),
        .q(o_z$q),
        .clock(o_z$clock)
    );
    span$o_rgb0 o_rgb0(
        .d(o_rgb0$d),
        .q(o_rgb0$q),
        .clock(o_rgb0$clock)
    );
    span$o_rgb1 o_rgb1(
        .d(o_rgb1$d),
        .q(o_rgb1$q),
        .clock(o_rgb1$clock)
    );
    span$o_rgb2 o_rgb2(
        .d(o_rgb2$d),
        .q(o_rgb2$q),
        .clock(o_rgb2$clock)
    );
    
    // Update code
    always @(*) begin
        busy$clock = clock;
        drop$clock = clock;
        left$clock = clock;
        x$clock = clock;
        last$clock = clock;
        at_last$clock = clock;
        y$clock = clock;
        a_z$clock = clock;
        a_c0$clock = clock;
        a_c1$clock = clock;
        a_c2$clock = clock;
        d_z$clock = clock;
        d_c0$clock = clock;
        d_c1$clock = clock;
        d_c2$clock = clock;
        o_valid$clock = clock;
        o_x$clock = clock;
        o_y$clock = clock;
        o_z$clock = clock;
        o_rgb0$clock = clock;
        o_rgb1$clock = clock;
        o_rgb2$clock = clock;
        busy$d = busy$q;
        drop$d = drop$q;
        left$d = left$q;
        x$d = x$q;
        last$d = last$q;
        at_last$d = at_last$q;
        y$d = y$q;
        a_z$d = a_z$q;
        a_c0$d = a_c0$q;
        a_c1$d = a_c1$q;
        a_c2$d = a_c2$q;
        d_z$d = d_z$q;
        d_c0$d = d_c0$q;
        d_c1$d = d_c1$q;
        d_c2$d = d_c2$q;
        o_valid$d = o_valid$q;
        o_x$d = o_x$q;
        o_y$d = o_y$q;
        o_z$d = o_z$q;
        o_rgb0$d = o_rgb0$q;
        o_rgb1$d = o_rgb1$q;
        o_rgb2$d = o_rgb2$q;
        width_x = ((width) & 13'h1fff);
        zp$x = a_z$q;
        c0$x = a_c0$q;
        c1$x = a_c1$q;
        c2$x = a_c2$q;
        valid = busy$q & ~drop$q;
        if (clip_x$on & (x$q >= width_x)) begin
            valid = 1'b0;
        end
        if (clip_z$on & (zp$neg | zp$over)) begin
            valid = 1'b0;
        end
        rgb0 = c0$low;
        if (c0$over) begin
            rgb0 = 32'hff;
        end
        if (c0$neg) begin
            rgb0 = 32'h0;
        end
        rgb1 = c1$low;
        if (c1$over) begin
            rgb1 = 32'hff;
        end
        if (c1$neg) begin
            rgb1 = 32'h0;
        end
        rgb2 = c2$low;
        if (c2$over) begin
            rgb2 = 32'hff;
        end
        if (c2$neg) begin
            rgb2 = 32'h0;
        end
        out$valid = o_valid$q;
        out$x = o_x$q;
        out$y = o_y$q;
        out$z = o_z$q;
        out$rgb0 = o_rgb0$q;
        out$rgb1 = o_rgb1$q;
        out$rgb2 = o_rgb2$q;
        idle = ~busy$q & ~o_valid$q;
        x_next = x$q + 32'h1;
        if (left$q) begin
            x_next = x$q - 32'h1;
        end
        advance = busy$q & (~o_valid$q | out$ready);
        ends = drop$q | at_last$q;
        ready = ~busy$q | (ends & advance);
        inp$ready = ready;
        accept = inp$valid & ready;
        if (out$ready) begin
            o_valid$d = 1'b0;
        end
        if (advance) begin
            o_valid$d = valid;
            o_x$d = ((x$q) & 10'h3ff);
            o_y$d = y$q;
            o_z$d = zp$low;
            o_rgb0$d = rgb0;
            o_rgb1$d = rgb1;
            o_rgb2$d = rgb2;
            if (ends) begin
                busy$d = 1'b0;
            end
            else begin
                x$d = x_next;
                at_last$d = x_next == last$q;
                if (left$q) begin
                    a_z$d = a_z$q - d_z$q;
                    a_c0$d = a_c0$q - d_c0$q;
                    a_c1$d = a_c1$q - d_c1$q;
                    a_c2$d = a_c2$q - d_c2$q;
                end
                else begin
                    a_z$d = a_z$q + d_z$q;
                    a_c0$d = a_c0$q + d_c0$q;
                    a_c1$d = a_c1$q + d_c1$q;
                    a_c2$d = a_c2$q + d_c2$q;
                end
            end
        end
        zl$x = inp$left_z;
        zr$x = inp$right_z;
        xl_neg$x = inp$xl;
        xr_neg$x = inp$xr;
        xl_on$a = inp$xl;
        xl_on$b = width_x;
        dropped = 1'b0;
        if (clip_x$on & (~xl_on$lt | xr_neg$neg)) begin
            dropped = 1'b1;
        end
        if (clip_z$on & ((zl$neg & zr$neg) | (zl$over & zr$over))) begin
            dropped = 1'b1;
        end
        last_column = width_x - 32'h1;
        xr_off = clip_x$on & (inp$xr >= width_x);
        if (xl_neg$neg & clip_x$on) begin
            x_first = inp$xr;
            x_last = 32'h0;
            one_pixel = inp$xr == 32'h0;
        end
        else begin
            x_first = inp$xl;
            x_last = inp$xr;
            one_pixel = inp$xl == inp$xr;
            if (xr_off) begin
                x_last = last_column;
                one_pixel = inp$xl == last_column;
            end
        end
        if (accept) begin
            busy$d = 1'b1;
            drop$d = dropped;
            x$d = x_first;
            last$d = x_last;
            at_last$d = one_pixel;
            y$d = inp$y;
            d_z$d = ((inp$ddx_z) & 36'hfffffffff);
            d_c0$d = ((inp$ddx_c0) & 32'hffffffff);
            d_c1$d = ((inp$ddx_c1) & 32'hffffffff);
            d_c2$d = ((inp$ddx_c2) & 32'hffffffff);
            left$d = xl_neg$neg & clip_x$on;
            if (xl_neg$neg & clip_x$on) begin
                a_z$d = inp$right_z;
                a_c0$d = inp$right_c0;
                a_c1$d = inp$right_c1;
                a_c2$d = inp$right_c2;
            end
            else begin
                a_z$d = inp$left_z;
                a_c0$d = inp$left_c0;
                a_c1$d = inp$left_c1;
                a_c2$d = inp$left_c2;
            end
        end
    end
    
endmodule // span


module span$a_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$a_c0


module span$a_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$a_c1


module span$a_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$a_c2


module span$a_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$a_z


module span$at_last(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$at_last


module span$busy(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$busy


module span$c0(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    span$c0$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // span$c0


module span$c0$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // span$c0$x_neg


module span$c1(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    span$c1$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // span$c1


module span$c1$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // span$c1$x_neg


module span$c2(x,neg,over,low);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    output reg  over;
    output reg  [7:0] low;
    
    // Constant declarations
    localparam  top = 33'h100000000;
    localparam  half = 33'h200000;
    localparam  shift = 8'h16;
    localparam  limit = 33'h100;
    
    // Stub signals
    reg  [31:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [32:0] ext;
    reg  [32:0] sum;
    reg  [32:0] shifted;
    
    // Sub module instances
    span$c2$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 33'h1ffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 33'h1ffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 8'hff);
    end
    
endmodule // span$c2


module span$c2$x_neg(x,neg);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 32'h80000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // span$c2$x_neg


module span$clip_x(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // span$clip_x


module span$clip_z(on);
    
    // Module arguments
    output reg  on;
    
    // Constant declarations
    localparam  value = 1'b1;
    
    // Update code
    always @(*) begin
        on = value;
    end
    
endmodule // span$clip_z


module span$d_c0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$d_c0


module span$d_c1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$d_c1


module span$d_c2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$d_c2


module span$d_z(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$d_z


module span$drop(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$drop


module span$last(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$last


module span$left(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$left


module span$o_rgb0(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$o_rgb0


module span$o_rgb1(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$o_rgb1


module span$o_rgb2(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$o_rgb2


module span$o_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$o_valid


module span$o_x(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$o_x


module span$o_y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$o_y


module span$o_z(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$o_z


module span$x(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$x


module span$xl_neg(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // span$xl_neg


module span$xl_on(a,b,lt);
    
    // Module arguments
    input wire  [12:0] a;
    input wire  [12:0] b;
    output reg  lt;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        lt = (a ^ half) < (b ^ half);
    end
    
endmodule // span$xl_on


module span$xr_neg(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // span$xr_neg


module span$y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // span$y


module span$zl(x,neg,over);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    output reg  over;
    
    // Constant declarations
    localparam  flip = 36'h800000000;
    localparam  lo = 36'h7fffe0000;
    localparam  hi = 36'hbfffe0000;
    localparam  can_over = 1'b1;
    
    // Update code
    always @(*) begin
        neg = (x ^ flip) < lo;
        over = can_over & ((x ^ flip) >= hi);
    end
    
endmodule // span$zl


module span$zp(x,neg,over,low);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    output reg  over;
    output reg  [15:0] low;
    
    // Constant declarations
    localparam  top = 37'h1000000000;
    localparam  half = 37'h20000;
    localparam  shift = 8'h12;
    localparam  limit = 37'h10000;
    
    // Stub signals
    reg  [35:0] x_neg$x;
    wire  x_neg$neg;
    
    // Local signals
    reg  [36:0] ext;
    reg  [36:0] sum;
    reg  [36:0] shifted;
    
    // Sub module instances
    span$zp$x_neg x_neg(
        .x(x_neg$x),
        .neg(x_neg$neg)
    );
    
    // Update code
    always @(*) begin
        x_neg$x = x;
        ext = ((x) & 37'h1fffffffff);
        if (x_neg$neg) begin
            ext = ((x) & 37'h1fffffffff) | top;
        end
        sum = ext + half;
        neg = sum >= top;
        shifted = sum >> shift;
        over = ~neg & (shifted >= limit);
        low = ((shifted) & 16'hffff);
    end
    
endmodule // span$zp


module span$zp$x_neg(x,neg);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 36'h800000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // span$zp$x_neg


module span$zr(x,neg,over);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  neg;
    output reg  over;
    
    // Constant declarations
    localparam  flip = 36'h800000000;
    localparam  lo = 36'h7fffe0000;
    localparam  hi = 36'hbfffe0000;
    localparam  can_over = 1'b1;
    
    // Update code
    always @(*) begin
        neg = (x ^ flip) < lo;
        over = can_over & ((x ^ flip) >= hi);
    end
    
endmodule // span$zr
